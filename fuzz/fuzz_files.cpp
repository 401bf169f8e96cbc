#include "fuzz_files.hpp"

#include <hdf5.h>
#include <stdlib.h>
#include <tbb/global_control.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>

#include "amrstream/error.hpp"

namespace amrstream::fuzz {

namespace fs = std::filesystem;

std::vector<std::string_view> splitParts(std::span<const std::uint8_t> input) {
  const std::string_view text(reinterpret_cast<const char*>(input.data()), input.size());
  std::vector<std::string_view> parts;
  std::size_t start = 0;
  for (std::size_t at; (at = text.find(kPartSeparator, start)) != std::string_view::npos;
       start = at + kPartSeparator.size())
    parts.push_back(text.substr(start, at - start));
  parts.push_back(text.substr(start));
  return parts;
}

std::string joinParts(const std::vector<std::string>& parts) {
  std::string joined;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    if (i > 0) joined += kPartSeparator;
    joined += parts[i];
  }
  return joined;
}

namespace {

// Never destroyed: removeScratch runs at exit, after static objects may have been destroyed.
const fs::path* scratch = nullptr;

void removeScratch() {
  std::error_code ignored;
  fs::remove_all(*scratch, ignored);
}

const fs::path& scratchDirectory() {
  if (scratch == nullptr) {
    std::string pattern = (fs::temp_directory_path() / "amrstream-fuzz-XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr)
      throw std::runtime_error("cannot create the fuzz scratch directory " + pattern);
    scratch = new fs::path(pattern);
    std::atexit(removeScratch);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
  return *scratch;
}

}  // namespace

const fs::path& freshScratchDirectory() {
  // One thread: runs are reproducible and AmrField's parallel checks stay cheap.
  static tbb::global_control oneThread(tbb::global_control::max_allowed_parallelism, 1);
  const fs::path& directory = scratchDirectory();
  for (const auto& entry : fs::directory_iterator(directory)) fs::remove_all(entry.path());
  return directory;
}

void writePart(const fs::path& directory, const std::string& name, std::string_view bytes) {
  if (bytes.empty()) return;
  const fs::path path = directory / name;
  fs::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out) throw std::runtime_error("cannot write the fuzz input file " + path.string());
}

void expectNoHdf5ObjectsOpen() {
  const ssize_t open = H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL);
  if (open != 0) {
    std::fprintf(stderr, "the reader left %zd HDF5 objects open\n", open);
    std::abort();
  }
}

void expectInputErrorAtMost(const std::function<void()>& read) {
  static const bool verbose = std::getenv("AMRSTREAM_FUZZ_VERBOSE") != nullptr;
  try {
    read();
    if (verbose) std::fprintf(stderr, "read\n");
  } catch (const InputError& e) {
    // a named refusal: expected
    if (verbose) std::fprintf(stderr, "refused: %s\n", e.what());
  }
}

}  // namespace amrstream::fuzz
