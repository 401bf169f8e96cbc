#pragma once
// What an AMReX plotfile says about itself (DatasetInfo):
//   time         the Header's time
//   periodicity  `geometry.is_periodic = X Y Z` (0 or 1 each) in the plotfile folder's `job_info`
//                (else a file named `*_job_info`, as PeleLMeX writes), where there is one;
//                otherwise unknown
//   units        unknown: plotfiles do not state them
//   levels       AMReX levels, 0 = coarsest. With refinement ratios of 2 internal level L is
//                level finest - L; with other ratios each level gets its own entry.

#include <filesystem>
#include <vector>

#include "amrstream/dataset_info.hpp"

namespace amrstream::formats {

// `internalLevels[l]`: our level of plotfile level l (log2 of its cell width in finest cells);
// `dimensions`: 2 or 3. Throws InputError naming the job_info file and line when its is_periodic
// line is malformed.
DatasetInfo readAmrexInfo(const std::filesystem::path& directory, double time,
                          const std::vector<int>& internalLevels, int dimensions);

}  // namespace amrstream::formats
