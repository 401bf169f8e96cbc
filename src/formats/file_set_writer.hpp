#pragma once
// Output files that appear together or not at all. Each file's bytes go to a temporary beside it
// (output::AtomicFile); commit() renames them over their targets in the order they were added,
// so the file that names the others should come last. When any write or rename fails, the
// targets this writer already renamed are removed again and the rest never appear: a full disk
// or a bad path leaves neither a truncated file nor a partial set. Every failure throws
// InputError naming the file and the system's reason.

#include <cstddef>
#include <filesystem>
#include <memory>
#include <span>
#include <vector>

#include "output/atomic_file.hpp"

namespace amrstream::formats {

class FileSetWriter {
 public:
  FileSetWriter() = default;
  FileSetWriter(const FileSetWriter&) = delete;
  FileSetWriter& operator=(const FileSetWriter&) = delete;
  ~FileSetWriter();  // removes the temporaries of a set that was not committed

  void add(const std::filesystem::path& target, std::span<const std::byte> bytes);
  void commit();

 private:
  std::vector<std::unique_ptr<output::AtomicFile>> files_;
  std::vector<std::filesystem::path> committed_;
};

}  // namespace amrstream::formats
