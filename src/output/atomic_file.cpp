#include "output/atomic_file.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <climits>
#include <csignal>
#include <cstdio>
#include <stdexcept>
#include <system_error>
#include <utility>

namespace amrstream::output {
namespace {

// The temporaries being written, for a signal handler to remove: slots of C strings that live in
// their AtomicFiles until those take them out again.
constexpr std::size_t kTrackedTemporaries = 256;
std::array<std::atomic<const char*>, kTrackedTemporaries> liveTemporaries{};

void track(const char* path) {
  for (auto& slot : liveTemporaries) {
    const char* empty = nullptr;
    if (slot.compare_exchange_strong(empty, path)) return;
  }  // all slots taken: this one is removed by its destructor only
}

void untrack(const char* path) {
  for (auto& slot : liveTemporaries) {
    const char* expected = path;
    if (slot.compare_exchange_strong(expected, nullptr)) return;
  }
}

extern "C" void removeTemporariesAndReraise(int signal) {
  for (auto& slot : liveTemporaries)
    if (const char* path = slot.exchange(nullptr)) ::unlink(path);  // async-signal-safe
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

// A file name's longest length here (NAME_MAX where the directory does not say).
std::size_t nameLimit(const std::filesystem::path& directory) {
  const long limit = ::pathconf(directory.empty() ? "." : directory.c_str(), _PC_NAME_MAX);
  return limit > 0 ? std::size_t(limit) : std::size_t(NAME_MAX);
}

std::filesystem::path temporaryBeside(const std::filesystem::path& target) {
  static std::atomic<unsigned> counter{0};
  const std::string suffix = fmt::format(".{}-{}.tmp", static_cast<long>(::getpid()), counter++);
  // A dot file, so file browsers (ParaView's included) do not list it next to finished output;
  // the target's name is cut where the whole would pass the file-name limit.
  std::string name = target.filename().string();
  const std::size_t limit = nameLimit(target.parent_path());
  if (1 + name.size() + suffix.size() > limit)
    name.resize(limit > suffix.size() + 1 ? limit - suffix.size() - 1 : 0);
  return target.parent_path() / ("." + name + suffix);
}

// Where the bytes go: through symbolic links at the target to the file they name (as cp writes,
// even where that file does not exist yet), so the links stay; the target itself otherwise. A
// loop fails naming the target.
std::filesystem::path destinationOf(const std::filesystem::path& target) {
  constexpr int kMaxLinks = 40;  // Linux's own limit in path resolution
  std::filesystem::path at = target;
  std::error_code error;
  for (int links = 0; std::filesystem::is_symlink(at, error); ++links) {
    if (links == kMaxLinks)
      throw std::system_error(
          std::make_error_code(std::errc::too_many_symbolic_link_levels),
          fmt::format("cannot write '{}' through its symbolic link", target.string()));
    const std::filesystem::path named = std::filesystem::read_symlink(at, error);
    if (error) break;
    at = named.is_absolute() ? named : at.parent_path() / named;
  }
  return at;
}

}  // namespace

void removeTemporariesOnSignals() {
  for (const int signal : {SIGINT, SIGTERM, SIGHUP})
    std::signal(signal, removeTemporariesAndReraise);
}

AtomicFile::AtomicFile(std::filesystem::path target)
    : target_(std::move(target)), destination_(destinationOf(target_)) {
  for (int attempt = 0; fd_ < 0; ++attempt) {
    temporary_ = temporaryBeside(destination_);
    // 0666 filtered by the umask: the final file gets the permissions of any newly created file,
    // or those of the file it replaces.
    fd_ = ::open(temporary_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd_ < 0 && (errno != EEXIST || attempt == 100)) fail(errno);
  }
  track(temporary_.c_str());
  struct stat replaced {};
  if (::stat(destination_.c_str(), &replaced) == 0 && S_ISREG(replaced.st_mode))
    ::fchmod(fd_, replaced.st_mode & 07777);
}

AtomicFile::~AtomicFile() {
  if (fd_ >= 0) {
    ::close(fd_);
    ::unlink(temporary_.c_str());
    untrack(temporary_.c_str());
  }
}

void AtomicFile::write(std::span<const std::byte> bytes) {
  while (!bytes.empty()) {
    const ssize_t written = ::write(fd_, bytes.data(), bytes.size());
    if (written < 0) {
      if (errno == EINTR) continue;
      fail(errno);
    }
    bytes = bytes.subspan(static_cast<std::size_t>(written));
    size_ += static_cast<std::uint64_t>(written);
  }
}

void AtomicFile::writeAt(std::uint64_t position, std::span<const std::byte> bytes) {
  if (position > size_ || bytes.size() > size_ - position) {
    throw std::logic_error(fmt::format("AtomicFile::writeAt past the {} bytes written to '{}'",
                                       size_, target_.string()));
  }
  while (!bytes.empty()) {
    const ssize_t written = ::pwrite(fd_, bytes.data(), bytes.size(), static_cast<off_t>(position));
    if (written < 0) {
      if (errno == EINTR) continue;
      fail(errno);
    }
    bytes = bytes.subspan(static_cast<std::size_t>(written));
    position += static_cast<std::uint64_t>(written);
  }
}

void AtomicFile::commit() {
  // fsync and close report write-back errors (NFS, full quota) that write() may defer.
  if (::fsync(fd_) != 0) fail(errno);
  const int fd = std::exchange(fd_, -1);
  untrack(temporary_.c_str());
  if (::close(fd) != 0) {
    const int error = errno;
    ::unlink(temporary_.c_str());
    fail(error);
  }
  if (std::rename(temporary_.c_str(), destination_.c_str()) != 0) {
    const int error = errno;
    ::unlink(temporary_.c_str());
    fail(error);
  }
}

void AtomicFile::fail(int error) const {
  throw std::system_error(error, std::generic_category(),
                          fmt::format("cannot write '{}'", target_.string()));
}

}  // namespace amrstream::output
