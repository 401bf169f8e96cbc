#pragma once
// The files a dataset is read from, so that no output of a run can replace one of them.

#include <filesystem>
#include <string>
#include <vector>

namespace amrstream::formats {

// The existing files and directories that reading `input` may open: nothing for builtin:KIND;
// an AMReX plotfile directory itself (everything under it); an ExaBricks .exa with the cells and
// scalar files it names; an Enzo dataset's parameter file, .hierarchy, .harrays and .cpuNNNN
// files (whichever of them the input names); any other file alone. Throws InputError, as loading
// would, for an input that does not exist or is in no known format.
std::vector<std::filesystem::path> datasetFiles(const std::string& input);

}  // namespace amrstream::formats
