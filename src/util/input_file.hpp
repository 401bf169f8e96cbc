#pragma once
// Checks made before an input file is opened or a size from it is trusted: the path names a
// regular file (a directory, FIFO, socket or device is refused by name, so nothing hangs on a
// FIFO without a writer or allocates the "size" of a directory), and every size, count or
// offset a header declares fits in the file and in 64-bit arithmetic.

#include <sys/stat.h>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <string>

#include "amrstream/error.hpp"

namespace amrstream {

// The size in bytes of the regular file at `path` (symbolic links followed). Throws InputError
// naming the path when it does not exist or is not a regular file.
inline std::uint64_t regularFileSize(const std::filesystem::path& path) {
  struct stat status {};
  if (::stat(path.c_str(), &status) != 0) {
    const int error = errno;
    throw InputError::fileError(path.string(), error,
                                error == ENOENT
                                    ? std::string("no such file")
                                    : std::string("cannot be read: ") + std::strerror(error));
  }
  if (S_ISDIR(status.st_mode)) throw InputError(path.string(), "is a directory, not a file");
  if (!S_ISREG(status.st_mode))
    throw InputError(path.string(), S_ISFIFO(status.st_mode)
                                        ? "is a FIFO (named pipe), not a regular file"
                                    : S_ISSOCK(status.st_mode) ? "is a socket, not a regular file"
                                                               : "is a device, not a regular file");
  return std::uint64_t(status.st_size);
}

// Throws InputError unless `count` items of `itemBytes` bytes starting at byte `offset` lie
// within a file of `fileBytes` bytes. `what` names the items in the message.
inline void requireWithinFile(const std::filesystem::path& path, std::uint64_t fileBytes,
                              std::uint64_t offset, std::uint64_t count, std::uint64_t itemBytes,
                              const std::string& what) {
  const std::uint64_t limit = std::numeric_limits<std::uint64_t>::max();
  const bool overflows = itemBytes != 0 && count > (limit - offset) / itemBytes;
  if (overflows || offset + count * itemBytes > fileBytes)
    throw InputError(path.string(), what + " declares " + std::to_string(count) + " items of " +
                                        std::to_string(itemBytes) + " bytes at byte " +
                                        std::to_string(offset) + ", past the end of the file (" +
                                        std::to_string(fileBytes) + " bytes)");
}

// a * b, or an InputError naming `source` and `what` when the product does not fit in 64 bits.
inline std::uint64_t checkedProduct(std::uint64_t a, std::uint64_t b, const std::string& source,
                                    const std::string& what) {
  if (a != 0 && b > std::numeric_limits<std::uint64_t>::max() / a)
    throw InputError(source, what + " (" + std::to_string(a) + " x " + std::to_string(b) +
                                 ") does not fit in 64 bits");
  return a * b;
}

}  // namespace amrstream
