#pragma once
// Everything the sampler reads, in the layout the GPU kernels also use: bricks, the vector
// values in brick order, the regions with their kd-tree, and the domain box.

#include <glm/glm.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "bricks/amr_field.hpp"
#include "bricks/brick_builder.hpp"
#include "bricks/region_builder.hpp"
#include "vector_selection.hpp"

namespace amrstream::flow {

struct VectorVolume {
  std::vector<shared::Brick> bricks;
  std::vector<glm::vec3> values;  // brick-ordered, see shared::Brick::valueOffset
  std::vector<std::uint32_t> cellIds;  // the field's cell at each value slot
  bricks::RegionSet regions;
  // Points outside the cells' bounding box [lower, upper) are out of the domain, even where the
  // half-cell padding of the brick domains reaches beyond it.
  bricks::CellBox domain;
  bricks::WorldTransform transform;
  std::string vectorName;
};

struct VolumeBuildTimes {
  double bricks = 0.0;  // seconds
  double regions = 0.0;
  double gather = 0.0;
};

VectorVolume buildVectorVolume(const bricks::AmrField& field, const VectorChannels& vector,
                               const bricks::BrickBuildOptions& options = {},
                               VolumeBuildTimes* times = nullptr);

// A scalar channel of `field` in the volume's brick order, for sampleScalar() and the renderer.
// Throws InputError listing the channels when `channel` is absent.
std::vector<float> gatherScalar(const bricks::AmrField& field, const VectorVolume& volume,
                                std::string_view channel);

}  // namespace amrstream::flow
