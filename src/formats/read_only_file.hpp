#pragma once
// A file opened for reading with pread from any number of threads at once: every read names its
// own offset, so no thread moves another's position.

#include <cstdint>
#include <filesystem>
#include <string>

namespace amrstream::formats {

class ReadOnlyFile {
 public:
  // Throws InputError naming the path and `what` when the file cannot be opened.
  ReadOnlyFile(const std::filesystem::path& path, const std::string& what);
  ~ReadOnlyFile();
  ReadOnlyFile(const ReadOnlyFile&) = delete;
  ReadOnlyFile& operator=(const ReadOnlyFile&) = delete;

  // Bytes [offset, offset + count) into `into`, all of them: InputError naming the path, `what`
  // and the range when the system fails or the file ends first (it shrank while being read).
  void readExactly(std::uint64_t offset, char* into, std::uint64_t count) const;

  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  std::string what_;
  int fd_;
};

}  // namespace amrstream::formats
