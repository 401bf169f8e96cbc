#include "formats/amrex/amrex_info.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <sstream>
#include <string>

#include "amrstream/error.hpp"
#include "formats/input_bytes.hpp"
#include "formats/text_numbers.hpp"

namespace amrstream::formats {

namespace {

namespace fs = std::filesystem;

// `job_info`, else the first `*_job_info` by name; empty when there is neither.
fs::path findJobInfo(const fs::path& directory) {
  std::error_code ec;
  if (fs::is_regular_file(directory / "job_info", ec)) return directory / "job_info";
  std::vector<fs::path> candidates;
  for (const auto& entry : fs::directory_iterator(directory, ec))
    if (entry.is_regular_file(ec) && entry.path().filename().string().ends_with("_job_info"))
      candidates.push_back(entry.path());
  std::ranges::sort(candidates);
  return candidates.empty() ? fs::path() : candidates.front();
}

// One 0/1 flag per axis of the plotfile (two in 2D; the slab's z is not periodic).
void readPeriodicity(const fs::path& jobInfo, int axes, DatasetInfo& info) {
  std::istringstream in(readWholeFile(jobInfo, "the job_info file"));
  const std::string key = "geometry.is_periodic";
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    const std::size_t start = line.find_first_not_of(" \t");
    if (start == std::string::npos || line.compare(start, key.size(), key) != 0) continue;
    std::istringstream words(line.substr(start + key.size()));
    std::string equals, extra;
    int flags[3] = {0, 0, 0};
    bool read = static_cast<bool>(words >> equals) && equals == "=";
    for (int a = 0; a < axes; ++a) read = read && (words >> flags[a]) && (flags[a] & ~1) == 0;
    if (!read || (words >> extra))
      throw InputError(fmt::format("{}:{}", jobInfo.string(), number),
                       fmt::format("'{}' is not '{} = {}' with 0 or 1 for each axis",
                                   excerpt(line.substr(start)), key, axes == 2 ? "X Y" : "X Y Z"));
    info.periodicKnown = true;
    for (int a = 0; a < 3; ++a) info.periodic[a] = flags[a] == 1;
  }
}

}  // namespace

DatasetInfo readAmrexInfo(const fs::path& directory, double time,
                          const std::vector<int>& internalLevels, int dimensions) {
  DatasetInfo info;
  info.format = "AMReX";
  info.dimensions = dimensions;
  info.time = time;
  const int finest = static_cast<int>(internalLevels.size()) - 1;
  info.finestFileLevel = finest;
  info.levelsCountDown = true;
  info.levelName = "AMReX level (0 = coarsest)";
  info.rootFileLevel = 0;
  bool ratiosOfTwo = true;
  for (int l = 0; l <= finest; ++l) ratiosOfTwo &= internalLevels[l] == finest - l;
  if (!ratiosOfTwo) {
    info.fileLevelOfInternal.assign(std::size_t(internalLevels.front()) + 1, -1);
    for (int l = 0; l <= finest; ++l) info.fileLevelOfInternal[internalLevels[l]] = l;
  }
  if (const fs::path jobInfo = findJobInfo(directory); !jobInfo.empty())
    readPeriodicity(jobInfo, dimensions, info);
  return info;
}

}  // namespace amrstream::formats
