#include "formats/input_bytes.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <fstream>

#include "amrstream/error.hpp"
#include "util/input_file.hpp"

namespace amrstream::formats {

std::uint64_t openRegularFile(std::ifstream& in, const std::filesystem::path& path,
                              const std::string& what) {
  const std::uint64_t size = regularFileSize(path);
  in.open(path, std::ios::binary);
  if (!in)
    throw InputError(path.string(), fmt::format("cannot open {}: {}", what, std::strerror(errno)));
  return size;
}

void readExactly(std::istream& in, const std::filesystem::path& path, std::uint64_t offset,
                 char* into, std::uint64_t count, const std::string& what) {
  in.read(into, static_cast<std::streamsize>(count));
  const auto got = static_cast<std::uint64_t>(in.gcount());
  if (got != count)
    throw InputError(path.string(),
                     fmt::format("{}: read {} of {} bytes from byte {}; the file is shorter than "
                                 "it was a moment ago (changed while being read?)",
                                 what, got, count, offset));
}

void refuseHoles(const std::filesystem::path& path, std::uint64_t size, const std::string& what) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return;  // the open that reads the file says why
  const off_t hole = ::lseek(fd, 0, SEEK_HOLE);
  ::close(fd);
  if (hole >= 0 && std::uint64_t(hole) < size)
    throw InputError(path.string(),
                     fmt::format("{} has a hole from byte {} (of {}): a range never written, "
                                 "which reads as zeros; the file is sparse or was not written "
                                 "whole",
                                 what, hole, size));
}

bool readBoundedLine(std::istream& in, std::string& line, std::size_t most,
                     const std::string& source, long number) {
  line.clear();
  std::array<char, 4096> piece;
  bool any = false;
  for (;;) {
    in.getline(piece.data(), piece.size());
    const auto got = static_cast<std::size_t>(in.gcount());
    any = any || got > 0;
    // The line ended at a '\n' (counted in `got`) unless the piece filled or the file ended.
    const bool ended = !in.fail() && !in.eof();
    line.append(piece.data(), ended ? got - 1 : got);
    if (line.size() > most)
      throw InputError(fmt::format("{}:{}", source, number),
                       fmt::format("the line is longer than {} bytes", most));
    if (ended) return true;
    if (in.eof()) {
      in.clear(std::ios::eofbit);
      return any;
    }
    in.clear();  // the piece filled: the line goes on
  }
}

std::string readWholeFile(const std::filesystem::path& path, const std::string& what,
                          std::uint64_t maxBytes) {
  std::ifstream in;
  const std::uint64_t size = openRegularFile(in, path, what);
  if (size > maxBytes)
    throw InputError(path.string(), fmt::format("{} has {} bytes, more than the {} accepted", what,
                                                size, maxBytes));
  refuseHoles(path, size, what);
  std::string bytes(static_cast<std::size_t>(size), '\0');
  readExactly(in, path, 0, bytes.data(), size, what);
  return bytes;
}

}  // namespace amrstream::formats
