#include <algorithm>

#include "amrstream/dataset.hpp"
#include "api/handles.hpp"
#include "flow/vector_volume.hpp"

namespace amrstream {

DatasetSummary summarize(const Dataset& dataset) {
  const bricks::AmrField& cells = cellsOf(dataset);
  DatasetSummary s;
  for (const Channel& c : cells.channels()) {
    const auto [min, max] = std::minmax_element(c.values.begin(), c.values.end());
    s.channels.push_back({c.name, *min, *max});
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
