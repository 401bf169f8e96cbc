#pragma once
// Output files and folders written under temporary names beside their targets and renamed over
// them together: commit() renames them in the order they were staged (the file that names the
// others should come last); when a rename fails, the targets already renamed are removed again.
// Destroying the stage before its commit removes the temporaries: a failed write leaves nothing
// under the targets' names. A folder replaces an existing folder of the same name whole.

#include <filesystem>
#include <vector>

namespace amrstream::formats {

class StagedOutputs {
 public:
  StagedOutputs() = default;
  StagedOutputs(const StagedOutputs&) = delete;
  StagedOutputs& operator=(const StagedOutputs&) = delete;
  ~StagedOutputs();

  // The temporary path to write `target`'s contents to (a file, or a folder the caller makes).
  std::filesystem::path stage(const std::filesystem::path& target);
  // Throws InputError naming the target and the system's reason when a rename fails.
  void commit();

 private:
  struct Staged {
    std::filesystem::path target, temporary;
  };
  std::vector<Staged> staged_;
};

}  // namespace amrstream::formats
