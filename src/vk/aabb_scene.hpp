#pragma once
// Acceleration structures over axis-aligned boxes (AABB procedural geometry), as the point
// location of docs/backends.md needs them.
//
// Global box ids. Box i of the input is primitive (i - firstBox) of the one geometry of the BLAS
// whose range [firstBox, firstBox + boxCount) holds i. The TLAS has one instance per BLAS, in
// order, with an identity transform, mask 0xFF, and instanceCustomIndex = firstBox. So a shader
// recovers the global id as
//     rayQueryGetIntersectionInstanceCustomIndexEXT(q, false)
//         + rayQueryGetIntersectionPrimitiveIndexEXT(q, false)       (ray query)
//     gl_InstanceCustomIndexEXT + gl_PrimitiveID                      (intersection shader)
// A BLAS holds at most maxPrimitiveCount boxes (2^24-1 on llvmpipe before Mesa 25.2.7), so large
// inputs are split into several BLAS. instanceCustomIndex has 24 bits, so the last BLAS must
// start below 2^24: inputs are limited to 0xFFFFFF + maxPrimitiveCount boxes.
//
// Geometry is not opaque (candidates must be confirmed by an exact containment test, since AABB
// candidates may be false positives) and carries NO_DUPLICATE_ANY_HIT_INVOCATION. Builds prefer
// fast trace and BLASes are compacted.

#include <vulkan/vulkan.h>

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "vk/acceleration_structure.hpp"

namespace amrstream::vk {

class Context;

struct AabbBlas {
  AccelerationStructure structure;
  uint32_t firstBox = 0;  // global id of its primitive 0 and its instance's custom index
  uint32_t boxCount = 0;
  VkDeviceSize buildSize = 0;  // accelerationStructureSize before compaction
};

// The largest BLAS buildAabbBlas makes: maxPrimitiveCount, or `override` when that is smaller
// and not 0 (tests use it to force splits).
uint32_t maxBoxesPerBlas(const Context& ctx, uint32_t override = 0);

// The most boxes one scene can hold: 0xFFFFFF + maxBoxesPerBlas(ctx, override).
uint64_t maxBoxesPerScene(const Context& ctx, uint32_t override = 0);

// Builds and compacts the BLASes over `boxes` (empty input: no BLAS); without `compact`, builds
// them only (one submission fewer and no wait for their sizes, for structures that live a short
// while). On return the builds are complete and visible to later acceleration-structure builds
// on the context's queue. Throws std::length_error for more boxes than the id scheme above can
// address.
std::vector<AabbBlas> buildAabbBlas(const Context& ctx, std::span<const VkAabbPositionsKHR> boxes,
                                    std::string_view name, uint32_t maxPrimitivesOverride = 0,
                                    bool compact = true);

// The box buffer (small box sets are read from host-visible memory; large ones from a
// device-local copy) and the scratch buffer of recordAabbBlas, kept from build to build and made
// larger when they are not large enough: for structures built frame after frame, which would
// otherwise make pinned and device memory every time.
struct BlasBuildBuffers {
  Buffer hostBoxes;
  Buffer deviceBoxes;
  std::optional<ScratchBuffer> scratch;
};

// buildAabbBlas's builds (not compacted) recorded into `cmd` instead of submitted: the BLASes
// are usable once `cmd` has run, and the buffers in `reuse` must not be reused or freed before.
std::vector<AabbBlas> recordAabbBlas(const Context& ctx, VkCommandBuffer cmd,
                                     std::span<const VkAabbPositionsKHR> boxes,
                                     std::string_view name, BlasBuildBuffers& reuse);

// The instance of `blas` in a TLAS as described above.
VkAccelerationStructureInstanceKHR tlasInstanceOf(const AabbBlas& blas);

// One instance per BLAS as described above. On return the build is complete and visible to any
// later command on the context's queue.
AccelerationStructure buildTlas(const Context& ctx, std::span<const AabbBlas> blases,
                                std::string_view name);

// The BLASes and the TLAS over them; `blases` is declared first so the TLAS goes first.
struct AabbScene {
  std::vector<AabbBlas> blases;
  AccelerationStructure tlas;
  uint32_t boxCount = 0;
};

AabbScene buildAabbScene(const Context& ctx, std::span<const VkAabbPositionsKHR> boxes,
                         std::string_view name, uint32_t maxPrimitivesOverride = 0);

}  // namespace amrstream::vk
