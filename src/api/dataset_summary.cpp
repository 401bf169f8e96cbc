#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <limits>
#include <utility>

#include "amrstream/dataset.hpp"
#include "api/handles.hpp"
#include "flow/vector_volume.hpp"

namespace amrstream {

DatasetSummary summarize(const Dataset& dataset) {
  const bricks::AmrField& cells = cellsOf(dataset);
  DatasetSummary s;
  for (const Channel& c : cells.channels()) {
    using Range = std::pair<float, float>;
    const Range range = tbb::parallel_reduce(
        tbb::blocked_range<std::size_t>(0, c.values.size()),
        Range{std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity()},
        [&](const tbb::blocked_range<std::size_t>& part, Range r) {
          for (std::size_t i = part.begin(); i != part.end(); ++i)
            r = {std::min(r.first, c.values[i]), std::max(r.second, c.values[i])};
          return r;
        },
        [](const Range& a, const Range& b) {
          return Range{std::min(a.first, b.first), std::max(a.second, b.second)};
        });
    s.channels.push_back({c.name, range.first, range.second});
  }
  flow::VolumeBuildTimes times;
  const flow::VectorVolume layout = flow::buildCellLayout(cells, {}, &times);
  s.bricks = layout.bricks.size();
  for (const shared::Brick& b : layout.bricks)
    s.largestBrickCells =
        std::max<std::size_t>(s.largestBrickCells, std::size_t(b.size.x) * b.size.y * b.size.z);
  s.bricksSeconds = times.bricks;
  const bricks::RegionSet& regions = layout.regions;
  s.regions = regions.regions.size();
  s.regionBrickEntries = regions.regionBricks.size();
  for (const shared::Region& r : regions.regions)
    s.largestRegionBricks = std::max<std::size_t>(s.largestRegionBricks, r.brickCount);
  s.treeNodes = regions.tree.size();
  s.regionsSeconds = times.regions;
  return s;
}

}  // namespace amrstream
