#pragma once
// The tube renderer on a Vulkan device (docs/rendering.md): tubes around traces, shaded with
// local lighting and ambient occlusion and coloured through a colour map, optionally in front of
// a scalar field ray-marched as a volume. Each frame adds one jittered sample per pixel (with its
// ambient-occlusion rays) to a running mean, so a still camera converges; changing the camera,
// the settings or the tubes starts the mean again.
//
// Tubes are intersected through the backend: the tubes' BVH traversed in a compute shader
// (`compute`), ray queries against their AABB acceleration structure (`rayquery`), or a ray
// tracing pipeline with a capsule intersection shader (`pipeline`). The volume is located through
// the regions' kd-tree on every backend.

#include <array>
#include <cstdint>
#include <future>
#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <string_view>
#include <utility>
#include <vector>

#include "../../shaders/glsl/shared/render_types.h"
#include "camera.hpp"
#include "flow/vector_volume.hpp"
#include "gpu/backend.hpp"
#include "render/image/image.hpp"
#include "render_kernel.hpp"
#include "tube_forest.hpp"
#include "tube_geometry.hpp"
#include "vk/aabb_scene.hpp"
#include "vk/buffer.hpp"
#include "vk/descriptor_pool.hpp"
#include "vk/descriptor_writes.hpp"
#include "vk/gpu_timer.hpp"
#include "vk/submission.hpp"
#include "vk/tlas_builder.hpp"

namespace amrstream::render {

struct RenderSettings {
  float tubeRadius = 0.5f;  // finest-cell units
  bool ambientOcclusion = true;
  std::uint32_t aoSamples = 4;  // rays per pixel and frame
  float aoDistance = 4.0f;      // finest-cell units
  ValueRange colourRange;       // the colour field's values at the ends of the colour map
  bool volume = false;          // needs context scalars
  bool logVolume = true;        // transfer function on log10 of the scalar
  ValueRange volumeRange;       // (log10) scalar values at the ends of the transfer function
  float volumeOpacity = 0.05f;  // extinction per finest cell at the top of the transfer function
  float volumeStepScale = 1.0f;
  glm::vec3 background{0.12f, 0.13f, 0.16f};
  bool flatBackground = false;     // else a gentle vertical gradient of `background`
  bool transparent = false;        // no background: the image's alpha is the coverage
  glm::vec3 outlineColour{0.75f};  // of segments with AMRSTREAM_OUTLINE_VALUE values
  // Below 1: tube radii follow the colour field, from this fraction of tubeRadius at the low end
  // of colourRange to tubeRadius at the high end (segmentRadius).
  float leastRadiusFraction = 1.0f;

  bool operator==(const RenderSettings&) const = default;
};

class TubeRenderer {
 public:
  // The context must have gpu::requiredCapabilities(backend) and outlive the renderer; so must
  // `volume`. `contextScalars` (brick-ordered, flow::gatherScalar; may be empty) is the field the
  // volume shows, reconstructed with `volume`'s interpolant (the linear one computes the scalar's
  // cell gradients here).
  TubeRenderer(const vk::Context& ctx, gpu::Backend backend, const flow::VectorVolume& volume,
               std::span<const float> contextScalars);
  // A background consolidation's task refers to the renderer.
  TubeRenderer(const TubeRenderer&) = delete;
  TubeRenderer& operator=(const TubeRenderer&) = delete;

  gpu::Backend backend() const { return kernel_.backend; }
  bool hasContextScalars() const { return hasScalars_; }

  // Replaces the tubes (builds the BVH or the acceleration structure); `radius` is the radius the
  // boxes are built for and must match RenderSettings::tubeRadius.
  void setTubes(std::span<const shared::TubeSegment> segments, float radius);
  // Adds `added` to the tubes (`all`: every tube, the added ones included, in any order). The
  // ray tracing backends build the added boxes' structure, merged with the last ones when they
  // are not much larger, and the instance list over all; `compute` does the same with its host
  // BVH (TubeForest). A change of radius, or more structures than either keeps, make it
  // setTubes(all, radius).
  void appendTubes(std::span<const shared::TubeSegment> added,
                   std::span<const shared::TubeSegment> all, float radius);
  static constexpr std::size_t kMaxAppendedStructures = 48;
  // Host seconds of the last appendTubes: writing the new segments to staging memory and
  // recording their copy, making the boxes and recording the structures' builds, writing the
  // instance list; then the one submission's wait for the device to do it all. All in
  // `structures` when it set the tubes whole.
  struct AppendTimes {
    double upload = 0.0, structures = 0.0, instances = 0.0, device = 0.0;
    double frameWait = 0.0;  // waiting for a frame submitted before (submitFrame)
  };
  const AppendTimes& lastAppendTimes() const { return appendTimes_; }
  // Rebuilds appended tubes as one structure, as setTubes would have built them (rays cross
  // fewer boxes): for when the tubes stop growing. With `inBackground`, `compute` builds its host
  // BVH on another thread while frames go on with the chunks, and the first renderFrame after it
  // is done puts it in place (the ray tracing backends build on the device, at once).
  void consolidateTubes(bool inBackground = false);
  // Waits for a background consolidation and puts its BVH in place.
  void finishConsolidation() { adoptConsolidated(true); }
  // The structures the tubes are in: compute's BVH chunks, or the bottom-level structures.
  std::size_t tubeStructures() const;
  std::size_t segmentCount() const { return segmentCount_; }
  float tubeRadius() const { return radius_; }
  void setColourMap(std::span<const glm::vec3> table);  // at least 2 entries
  void resize(std::uint32_t width, std::uint32_t height);

  // Adds one frame; waits for it. Throws std::invalid_argument when settings.tubeRadius differs
  // from the tubes' or the volume is asked for without context scalars.
  void renderFrame(const OrbitCamera& camera, const RenderSettings& settings) {
    submitFrame(camera, settings);
    waitForFrame();
  }
  // The same without waiting: the device renders the tubes as they stand while the host goes
  // on. Every call that changes what the frame reads (appendTubes after its host work, setTubes,
  // resize, ...) waits for it first, and so do readImage and waitForFrame.
  void submitFrame(const OrbitCamera& camera, const RenderSettings& settings);
  void waitForFrame() const;
  std::uint32_t framesAccumulated() const { return frames_; }
  std::optional<double> lastFrameSeconds() const { return lastFrameSeconds_; }

  std::uint32_t width() const { return width_; }
  std::uint32_t height() const { return height_; }
  // RGBA8 pixels, top row first: width * height * 4 bytes; TRANSFER_SRC.
  const vk::Buffer& pixels() const { return pixels_; }
  Image readImage() const;

 private:
  // Points the descriptor set at the current buffers; after any of them was replaced.
  void writeDescriptors();
  // The tubes' acceleration structure, or compute's BVH (the region tree stands in while there
  // is no BVH buffer).
  vk::DescriptorTarget tubeStructure() const;
  // Puts the background consolidation's BVH in place once it is done; with `wait`, waits for it.
  void adoptConsolidated(bool wait);
  // Ends a background consolidation before the tubes change, dropping its result.
  void dropConsolidation();
  // Makes `buffer` hold at least `contents` (growing it, keeping what it holds, at once) and
  // records into `cmd` the copy of the byte ranges [first, end) of `contents` into it, through
  // the next of appendStaging_ (stagingUsed_ counts them per append).
  void writeRanges(vk::Buffer& buffer, std::string_view name, std::span<const std::byte> contents,
                   std::span<const std::pair<std::size_t, std::size_t>> ranges,
                   VkCommandBuffer cmd);

  const vk::Context* ctx_;
  const flow::VectorVolume* volume_;
  RenderKernel kernel_;
  vk::Buffer bricks_, scalars_, scalarGradients_, regions_, regionBricks_, tree_;
  bool hasScalars_ = false;
  bool linearVolume_ = false;
  vk::Buffer segments_, bvhNodes_;
  std::vector<shared::TubeSegment> deviceOrder_;  // segments_ as the ray tracing backends hold it
  // After appendTubes, scene_'s BLASes are instanced by appendedTlas_, not by scene_->tlas.
  bool appended_ = false;
  std::optional<vk::TlasBuilder> appendedTlas_;
  std::array<vk::Buffer, 2> appendStaging_;  // one per buffer an append writes (compute: two)
  std::size_t stagingUsed_ = 0;
  vk::BlasBuildBuffers appendBuild_;  // the appended structures' box and scratch buffers
  TubeForest forest_;  // compute: the segments and BVH nodes as the buffers hold them
  // compute: the whole BVH built from forest_ on another thread, with its arrays already in
  // staging buffers (declared after forest_: destroyed, and so waited for, first).
  struct Consolidated {
    TubeForest forest;
    vk::Buffer segments, nodes;
  };
  std::future<Consolidated> consolidated_;
  AppendTimes appendTimes_;
  std::optional<vk::AabbScene> scene_;
  std::size_t segmentCount_ = 0;
  float radius_ = 0.0f;
  glm::vec3 tubesLower_{0.0f}, tubesUpper_{0.0f};  // the tubes' bounding box, radius included
  vk::Buffer colourMap_;
  vk::Buffer accumulation_, pixels_;
  std::uint32_t width_ = 0, height_ = 0;
  vk::Buffer params_;  // host-visible, rewritten each frame
  std::optional<vk::DescriptorPool> pool_;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
  bool descriptorsStale_ = true;
  vk::GpuTimer timer_;
  std::uint32_t frames_ = 0;
  std::optional<OrbitCamera> lastCamera_;
  std::optional<RenderSettings> lastSettings_;
  mutable std::optional<double> lastFrameSeconds_;
  // The frame in flight (declared last: destroyed, and so waited for, before what it reads).
  mutable vk::Submission frame_;
};

}  // namespace amrstream::render
