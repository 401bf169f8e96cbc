#include "formats/read_only_file.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "amrstream/error.hpp"

namespace amrstream::formats {

ReadOnlyFile::ReadOnlyFile(const std::filesystem::path& path, const std::string& what)
    : path_(path), what_(what), fd_(::open(path.c_str(), O_RDONLY | O_CLOEXEC)) {
  if (fd_ < 0)
    throw InputError(path.string(), fmt::format("cannot open {}: {}", what, std::strerror(errno)));
}

ReadOnlyFile::~ReadOnlyFile() { ::close(fd_); }

void ReadOnlyFile::readExactly(std::uint64_t offset, char* into, std::uint64_t count) const {
  std::uint64_t got = 0;
  while (got < count) {
    const ssize_t n = ::pread(fd_, into + got, count - got, off_t(offset + got));
    if (n < 0 && errno == EINTR) continue;
    if (n < 0)
      throw InputError(path_.string(), fmt::format("{}: reading {} bytes from byte {} failed: {}",
                                                   what_, count, offset, std::strerror(errno)));
    if (n == 0)
      throw InputError(path_.string(),
                       fmt::format("{}: read {} of {} bytes from byte {}; the file is shorter "
                                   "than it was a moment ago (changed while being read?)",
                                   what_, got, count, offset));
    got += std::uint64_t(n);
  }
}

}  // namespace amrstream::formats
