#pragma once
// Reads of input files that trust nothing: the path must name a regular file before it is opened
// (a directory, FIFO or device is refused by name, so nothing hangs or allocates a bogus size),
// sizes are bounded before anything is allocated, and every read must deliver all the bytes the
// file had when its size was taken, so a file that shrinks while it is read fails by name
// instead of being parsed short or read as garbage.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

namespace amrstream::formats {

// Text and header files larger than this are refused: no metadata file is near it, and a sparse
// file claiming terabytes must not become an allocation.
inline constexpr std::uint64_t kMaxTextFileBytes = std::uint64_t{1} << 30;

// The whole file as bytes. `what` names the file's role in errors ("the plotfile Header").
std::string readWholeFile(const std::filesystem::path& path, const std::string& what,
                          std::uint64_t maxBytes = kMaxTextFileBytes);

// Reads exactly `count` bytes into `into` from `in` (opened on `path`), which must be at byte
// `offset`; throws InputError naming the path, the offset and how many bytes came when fewer do.
void readExactly(std::istream& in, const std::filesystem::path& path, std::uint64_t offset,
                 char* into, std::uint64_t count, const std::string& what);

// Throws InputError naming `path` when the file has a hole (a range never written, which reads
// as zeros: the whole of a sparse file made by truncate) before `size`: a text file or a .cells
// file cannot hold one, since zeros there are not text and repeat one cell. Where the file
// system does not tell holes from data (no SEEK_HOLE), nothing is found.
void refuseHoles(const std::filesystem::path& path, std::uint64_t size, const std::string& what);

// The next line of `in`, line `number` of `source`, without its '\n', into `line`; false at
// the end. InputError naming source:number when the line passes `most` bytes, before it is held.
bool readBoundedLine(std::istream& in, std::string& line, std::size_t most,
                     const std::string& source, long number);

// Opens `path` for binary reading after checking that it is a regular file (InputError
// otherwise, or when it cannot be opened); returns the size the check found.
std::uint64_t openRegularFile(std::ifstream& in, const std::filesystem::path& path,
                              const std::string& what);

}  // namespace amrstream::formats
