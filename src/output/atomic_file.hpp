#pragma once
// A file that appears at its path only when complete: bytes go to a hidden temporary file in the
// same directory (so the final rename stays on one file system and is atomic), and commit()
// renames it over the target. Destroying an uncommitted AtomicFile removes the temporary, so a
// failed or interrupted write never leaves a partial file under the target name. Parts already
// written can be overwritten in place (writeAt) until the commit, for headers whose contents are
// known only once the rest is written. The file replaced keeps its permissions; a symbolic link
// at the target stays, and the file it names is replaced.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>

#include "output/byte_sink.hpp"

namespace amrstream::output {

// Installs handlers of SIGINT, SIGTERM and SIGHUP that remove the temporaries of every AtomicFile
// being written, then end the process as the signal would have.
void removeTemporariesOnSignals();

class AtomicFile final : public ByteSink {
 public:
  // Creates the temporary file; throws std::system_error (a std::runtime_error) naming `target`
  // and the OS reason when it cannot.
  explicit AtomicFile(std::filesystem::path target);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  // Unbuffered; throws std::system_error naming the target on any failure (ENOSPC, EFBIG, EIO).
  void write(std::span<const std::byte> bytes) override;
  // Writes over bytes already written, from `position` on; the end of the file does not move.
  // Throws std::logic_error when the range reaches past what was written.
  void writeAt(std::uint64_t position, std::span<const std::byte> bytes);
  // Flushes to disk, closes and renames over the target. The file is unusable afterwards.
  void commit();

  const std::filesystem::path& target() const { return target_; }

 private:
  [[noreturn]] void fail(int error) const;

  std::filesystem::path target_;
  std::filesystem::path destination_;  // the target, or the file its symbolic link names
  std::filesystem::path temporary_;
  int fd_ = -1;
  std::uint64_t size_ = 0;  // bytes written so far
};

}  // namespace amrstream::output
