#include "formats/staged_outputs.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include "amrstream/error.hpp"

namespace amrstream::formats {

namespace fs = std::filesystem;

StagedOutputs::~StagedOutputs() {
  std::error_code ignored;
  for (const Staged& s : staged_) fs::remove_all(s.temporary, ignored);
}

fs::path StagedOutputs::stage(const fs::path& target) {
  const fs::path temporary =
      target.parent_path() /
      fmt::format(".{}.tmp-{}-{}", target.filename().string(), ::getpid(), staged_.size());
  std::error_code ignored;
  fs::remove_all(temporary, ignored);
  staged_.push_back({target, temporary});
  return temporary;
}

void StagedOutputs::commit() {
  std::vector<fs::path> renamed;
  for (const Staged& s : staged_) {
    std::error_code error;
    if (fs::is_directory(s.temporary, error) && fs::is_directory(s.target, error))
      fs::remove_all(s.target, error);  // a folder is replaced whole
    fs::rename(s.temporary, s.target, error);
    if (!error) {
      renamed.push_back(s.target);
      continue;
    }
    std::error_code ignored;
    for (const fs::path& done : renamed) fs::remove_all(done, ignored);
    throw InputError(s.target.string(), fmt::format("cannot write it: {}", error.message()));
  }
  staged_.clear();
}

}  // namespace amrstream::formats
