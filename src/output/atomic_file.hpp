#pragma once
// A file that appears at its path only when complete: bytes go to a hidden temporary file in the
// same directory (so the final rename stays on one file system and is atomic), and commit()
// renames it over the target. Destroying an uncommitted AtomicFile removes the temporary, so a
// failed or interrupted write never leaves a partial file under the target name.

#include <cstddef>
#include <filesystem>
#include <span>

namespace amrstream::output {

class AtomicFile {
 public:
  // Creates the temporary file; throws std::system_error (a std::runtime_error) naming `target`
  // and the OS reason when it cannot.
  explicit AtomicFile(std::filesystem::path target);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  // Unbuffered; throws std::system_error naming the target on any failure (ENOSPC, EFBIG, EIO).
  void write(std::span<const std::byte> bytes);
  // Flushes to disk, closes and renames over the target. The file is unusable afterwards.
  void commit();

  const std::filesystem::path& target() const { return target_; }

 private:
  [[noreturn]] void fail(int error) const;

  std::filesystem::path target_;
  std::filesystem::path temporary_;
  int fd_ = -1;
};

}  // namespace amrstream::output
