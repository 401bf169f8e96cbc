#include "formats/input_bytes.hpp"

#include <fmt/format.h>

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

std::string readWholeFile(const std::filesystem::path& path, const std::string& what,
                          std::uint64_t maxBytes) {
  std::ifstream in;
  const std::uint64_t size = openRegularFile(in, path, what);
  if (size > maxBytes)
    throw InputError(path.string(), fmt::format("{} has {} bytes, more than the {} accepted", what,
                                                size, maxBytes));
  std::string bytes(static_cast<std::size_t>(size), '\0');
  readExactly(in, path, 0, bytes.data(), size, what);
  return bytes;
}

}  // namespace amrstream::formats
