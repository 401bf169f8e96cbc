#pragma once
// Paths that are not regular files, for the readers' refusal tests: a FIFO (named pipe) and a
// call of a reader on it that cannot hang the test. A reader must refuse a FIFO before opening
// it; one that opens it instead blocks until a writer comes, so the call gives it one that closes
// at once (the reader then sees end of file) and fails the test.

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <future>
#include <string>
#include <thread>

#include "input_error_of.hpp"

namespace amrstream::testing {

inline void makeFifo(const std::filesystem::path& path) {
  ASSERT_EQ(::mkfifo(path.c_str(), 0600), 0) << path << ": " << std::strerror(errno);
}

// The InputError message of `read`, which runs on another thread. When it has not returned after
// `patience`, the test fails and `fifo` gets a writer that closes at once, once a second until
// `read` returns.
inline std::string inputErrorWithoutHanging(
    const std::filesystem::path& fifo, const std::function<void()>& read,
    std::chrono::seconds patience = std::chrono::seconds(10)) {
  std::packaged_task<std::string()> task([read] { return inputErrorOf(read); });
  std::future<std::string> result = task.get_future();
  std::thread reader(std::move(task));
  if (result.wait_for(patience) != std::future_status::ready) {
    ADD_FAILURE() << "the reader blocked on the FIFO " << fifo << " instead of refusing it";
    do {
      const int fd = ::open(fifo.c_str(), O_WRONLY | O_NONBLOCK);
      if (fd >= 0) ::close(fd);
    } while (result.wait_for(std::chrono::seconds(1)) != std::future_status::ready);
  }
  reader.join();
  return result.get();
}

// Makes `path` a sparse file of `size` bytes holding `data` first; false where the file system
// does not report the hole after it (no SEEK_HOLE), so the caller skips.
inline bool makeSparseFile(const std::filesystem::path& path, const std::string& data,
                           std::uintmax_t size) {
  {
    std::ofstream out(path, std::ios::binary);
    out << data;
  }
  std::filesystem::resize_file(path, size);
  const int fd = ::open(path.c_str(), O_RDONLY);
  const off_t hole = fd >= 0 ? ::lseek(fd, 0, SEEK_HOLE) : -1;
  if (fd >= 0) ::close(fd);
  return hole >= 0 && std::uintmax_t(hole) < size;
}

}  // namespace amrstream::testing
