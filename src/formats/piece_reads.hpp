#pragma once
// Large ranges of input files read in pieces on all cores (pread on one descriptor), as fast as
// the page cache or the storage delivers them: one core copying from the page cache reaches a
// fraction of what the memory allows. Every piece must come whole, as readExactly requires.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <span>
#include <string>

namespace amrstream::formats {

// Bytes [offset, offset + count) of `path` into `into`. Throws InputError naming the path,
// `what` and the piece that came short (a file that shrank while it was read).
void readInPieces(const std::filesystem::path& path, std::uint64_t offset, char* into,
                  std::uint64_t count, const std::string& what);

// Bytes [offset, offset + count) of `path` in pieces of `pieceBytes` (the last may be shorter),
// each handed to `use(first, bytes)` (`first`: its offset from `offset`) on the core that read it,
// in a buffer of that core's, in no particular order. Errors as readInPieces; an exception
// `use` throws ends the reads and comes out of this call.
void forEachPiece(const std::filesystem::path& path, std::uint64_t offset, std::uint64_t count,
                  std::uint64_t pieceBytes, const std::string& what,
                  const std::function<void(std::uint64_t first, std::span<const char> bytes)>& use);

}  // namespace amrstream::formats
