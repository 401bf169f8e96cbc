#include "formats/file_set_writer.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <system_error>

#include "amrstream/error.hpp"

namespace amrstream::formats {

namespace {

[[noreturn]] void rethrowNamed(const std::filesystem::path& target, const std::system_error& e) {
  throw InputError(target.string(), "cannot write the file: " + e.code().message());
}

// An exclusive lock on a directory while it is held (none where the directory cannot be opened,
// as on some network file systems: the renames then go unguarded, as before).
class DirectoryLock {
 public:
  explicit DirectoryLock(const std::filesystem::path& directory)
      : fd_(::open(directory.empty() ? "." : directory.c_str(),
                   O_RDONLY | O_DIRECTORY | O_CLOEXEC)) {
    if (fd_ >= 0)
      while (::flock(fd_, LOCK_EX) != 0 && errno == EINTR) {
      }
  }
  ~DirectoryLock() {
    if (fd_ >= 0) ::close(fd_);  // closing releases the lock
  }
  DirectoryLock(const DirectoryLock&) = delete;
  DirectoryLock& operator=(const DirectoryLock&) = delete;

 private:
  int fd_;
};

}  // namespace

FileSetWriter::~FileSetWriter() = default;

void FileSetWriter::add(const std::filesystem::path& target, std::span<const std::byte> bytes) {
  try {
    auto file = std::make_unique<output::AtomicFile>(target);
    file->write(bytes);
    files_.push_back(std::move(file));
  } catch (const std::system_error& e) {
    rethrowNamed(target, e);
  }
}

void FileSetWriter::commit() {
  if (files_.empty()) return;
  // Another writer of the same set (two `gen` runs with one prefix) renames its files before or
  // after this one, never between: the set that appears is one run's.
  const DirectoryLock lock(files_.front()->target().parent_path());
  for (auto& file : files_) {
    try {
      file->commit();
      committed_.push_back(file->target());
    } catch (const std::system_error& e) {
      std::error_code ignored;
      for (const std::filesystem::path& done : committed_) std::filesystem::remove(done, ignored);
      rethrowNamed(file->target(), e);
    }
  }
  files_.clear();
}

}  // namespace amrstream::formats
