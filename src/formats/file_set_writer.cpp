#include "formats/file_set_writer.hpp"

#include <system_error>

#include "amrstream/error.hpp"

namespace amrstream::formats {

namespace {

[[noreturn]] void rethrowNamed(const std::filesystem::path& target, const std::system_error& e) {
  throw InputError(target.string(), "cannot write the file: " + e.code().message());
}

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
