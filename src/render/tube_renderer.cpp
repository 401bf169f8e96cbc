#include "tube_renderer.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "bricks/descent_tree.hpp"
#include "flow/cell_gradients.hpp"
#include "scene_space.hpp"
#include "tube_forest.hpp"
#include "util/stopwatch.hpp"
#include "vk/buffer_transfer.hpp"
#include "vk/commands.hpp"
#include "vk/context.hpp"

namespace amrstream::render {

namespace {

constexpr VkBufferUsageFlags kStorage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
// Segments that appendTubes may move into a larger buffer.
constexpr VkBufferUsageFlags kAppendable = kStorage | VK_BUFFER_USAGE_TRANSFER_SRC_BIT;

std::vector<VkAabbPositionsKHR> segmentBoxes(std::span<const shared::TubeSegment> segments,
                                             float radius) {
  std::vector<VkAabbPositionsKHR> boxes(segments.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, segments.size(), 1 << 14),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t i = range.begin(); i != range.end(); ++i) {
                        const glm::vec3 lo = glm::min(segments[i].a, segments[i].b) - radius;
                        const glm::vec3 hi = glm::max(segments[i].a, segments[i].b) + radius;
                        boxes[i] = {lo.x, lo.y, lo.z, hi.x, hi.y, hi.z};
                      }
                    });
  return boxes;
}

// Where parallel rays start: on a plane across the view just in front of everything they may
// meet (the tubes, and the domain when the volume shows), not further: the capsule test loses
// thin tubes to float rounding when rays start thousands of cells away.
float orthographicStart(const OrbitCamera& camera, const CameraFrame& view,
                        const RenderSettings& settings, const flow::VectorVolume& volume,
                        glm::vec3 tubesLower, glm::vec3 tubesUpper) {
  float nearest = 0.0f;
  const auto include = [&](glm::vec3 lower, glm::vec3 upper) {
    for (int corner = 0; corner < 8; ++corner) {
      const glm::vec3 p((corner & 1) ? upper.x : lower.x, (corner & 2) ? upper.y : lower.y,
                        (corner & 4) ? upper.z : lower.z);
      nearest = std::max(nearest, -glm::dot(p - camera.target, view.forward));
    }
  };
  include(tubesLower, tubesUpper);
  if (settings.volume) {
    const glm::vec3 scale(sceneScaleOf(volume.transform));
    include(glm::vec3(volume.domain.lower) * scale, glm::vec3(volume.domain.upper) * scale);
  }
  return nearest + 1.0f;
}

shared::RenderParams makeParams(const OrbitCamera& camera, const RenderSettings& settings,
                                const flow::VectorVolume& volume, std::uint32_t width,
                                std::uint32_t height, std::uint32_t frame, std::size_t segmentCount,
                                bool linearVolume, glm::vec3 tubesLower, glm::vec3 tubesUpper) {
  const CameraFrame view = cameraFrame(camera);
  const bool orthographic = camera.projection == Projection::Orthographic;
  shared::RenderParams p{};
  p.eye = view.eye;
  p.forward = view.forward;
  p.right = view.right;
  p.up = view.up;
  p.halfHeight = halfHeightAtUnitDistance(camera);
  if (orthographic) {
    p.eye =
        camera.target -
        orthographicStart(camera, view, settings, volume, tubesLower, tubesUpper) * view.forward;
    p.halfHeight *= camera.distance;
  }
  p.aspect = float(width) / float(height);
  p.frameIndex = frame;
  p.flags = (settings.ambientOcclusion ? AMRSTREAM_RENDER_AO : 0u) |
            (settings.volume ? AMRSTREAM_RENDER_VOLUME : 0u) |
            (settings.logVolume ? AMRSTREAM_RENDER_LOG_VOLUME : 0u) |
            (linearVolume ? AMRSTREAM_RENDER_LINEAR_VOLUME : 0u) |
            (orthographic ? AMRSTREAM_RENDER_ORTHOGRAPHIC : 0u) |
            (settings.flatBackground ? AMRSTREAM_RENDER_FLAT_BACKGROUND : 0u) |
            (settings.transparent ? AMRSTREAM_RENDER_TRANSPARENT : 0u) |
            (settings.leastRadiusFraction < 1.0f ? AMRSTREAM_RENDER_RADIUS_BY_VALUE : 0u);
  p.imageSize = {width, height};
  p.segmentCount = static_cast<std::uint32_t>(segmentCount);
  p.tubeRadius = settings.tubeRadius;
  // A key light above and to the left of the viewer.
  p.lightDirection = glm::normalize(-view.forward + 0.6f * view.up - 0.5f * view.right);
  p.aoSamples = settings.aoSamples;
  p.background = settings.background;
  p.outlineColour = settings.outlineColour;
  p.leastRadiusFraction = settings.leastRadiusFraction;
  p.aoDistance = settings.aoDistance;
  p.domainLower = glm::vec3(volume.domain.lower);
  p.domainUpper = glm::vec3(volume.domain.upper);
  p.sceneScale = glm::vec3(sceneScaleOf(volume.transform));
  p.valueMin = settings.colourRange.min;
  p.valueMax = settings.colourRange.max;
  p.volumeMin = settings.volumeRange.min;
  p.volumeMax = settings.volumeRange.max;
  p.volumeOpacity = settings.volumeOpacity;
  p.volumeStepScale = settings.volumeStepScale;
  return p;
}

}  // namespace

TubeRenderer::TubeRenderer(const vk::Context& ctx, gpu::Backend backend,
                           const flow::VectorVolume& volume, std::span<const float> contextScalars)
    : ctx_(&ctx),
      volume_(&volume),
      kernel_(createRenderKernel(ctx, backend)),
      timer_(ctx),
      frame_(ctx) {
  if (!contextScalars.empty() && contextScalars.size() != volume.values.size())
    throw std::invalid_argument("TubeRenderer: context scalars must have one value per cell");
  hasScalars_ = !contextScalars.empty();
  bricks_ = vk::uploadToDeviceLocal(ctx, volume.bricks, kStorage, "bricks");
  scalars_ = vk::uploadToDeviceLocal(ctx, contextScalars, kStorage, "context scalars");
  linearVolume_ = hasScalars_ && volume.interpolant == flow::Interpolant::Linear;
  const std::vector<glm::vec3> gradients =
      linearVolume_ ? flow::cellGradients(volume, contextScalars, 1) : std::vector<glm::vec3>(1);
  scalarGradients_ = vk::uploadToDeviceLocal(ctx, gradients, kStorage, "context scalar gradients");
  regions_ = vk::uploadToDeviceLocal(ctx, volume.regions.regions, kStorage, "regions");
  regionBricks_ =
      vk::uploadToDeviceLocal(ctx, volume.regions.regionBricks, kStorage, "region bricks");
  tree_ = vk::uploadToDeviceLocal(ctx, bricks::buildDescentTree(volume.regions).bytes(), kStorage,
                                  "region tree");
  params_ = vk::Buffer::upload(ctx, sizeof(shared::RenderParams),
                               VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, "render params");

  const std::array<VkDescriptorPoolSize, 3> sizes{
      {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1},
       {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, AMRSTREAM_RENDER_BINDING_COUNT - 1},
       {VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR, 1}}};
  pool_.emplace(ctx, 1, std::span(sizes).first(backend == gpu::Backend::Compute ? 2 : 3));
  set_ = pool_->allocate(kernel_.setLayout.get());

  setTubes({}, 0.0f);
  const std::array<glm::vec3, 2> grey{glm::vec3(0.5f), glm::vec3(0.5f)};
  setColourMap(grey);
}

void TubeRenderer::setTubes(std::span<const shared::TubeSegment> segments, float radius) {
  dropConsolidation();
  waitForFrame();
  segmentCount_ = segments.size();
  radius_ = radius;
  tubesLower_ = glm::vec3(INFINITY), tubesUpper_ = glm::vec3(-INFINITY);
  for (const shared::TubeSegment& s : segments) {
    tubesLower_ = glm::min(tubesLower_, glm::min(s.a, s.b) - radius);
    tubesUpper_ = glm::max(tubesUpper_, glm::max(s.a, s.b) + radius);
  }
  if (segments.empty()) tubesLower_ = tubesUpper_ = glm::vec3(0.0f);
  scene_.reset();
  appended_ = false;
  bvhNodes_ = {};
  if (kernel_.backend == gpu::Backend::Compute) {
    forest_.reset(segments, radius);
    segments_ = vk::uploadToDeviceLocal(*ctx_, forest_.segments(), kAppendable, "tube segments");
    bvhNodes_ = vk::uploadToDeviceLocal(*ctx_, forest_.nodes(), kAppendable, "tube BVH");
  } else {
    segments_ = vk::uploadToDeviceLocal(*ctx_, segments, kAppendable, "tube segments");
    scene_ = vk::buildAabbScene(*ctx_, segmentBoxes(segments, radius), "tubes");
    deviceOrder_.assign(segments.begin(), segments.end());
  }
  frames_ = 0;
  descriptorsStale_ = true;
}

void TubeRenderer::writeRanges(vk::Buffer& buffer, std::string_view name,
                               std::span<const std::byte> contents,
                               std::span<const std::pair<std::size_t, std::size_t>> ranges,
                               VkCommandBuffer cmd) {
  if (buffer.size() < contents.size()) {  // room for as many again, keeping what is there
    vk::Buffer grown = vk::Buffer::deviceLocal(
        *ctx_, 2 * contents.size(), kAppendable | VK_BUFFER_USAGE_TRANSFER_DST_BIT, name);
    vk::submitAndWait(*ctx_, [&](VkCommandBuffer cmd) {
      const VkBufferCopy region{0, 0, buffer.size()};
      if (region.size > 0) vkCmdCopyBuffer(cmd, buffer.handle(), grown.handle(), 1, &region);
      vk::memoryBarrier(cmd, vk::access::kTransferWrite, vk::access::kAny);
    });
    buffer = std::move(grown);
  }
  std::size_t bytes = 0;
  for (const auto& [first, end] : ranges) bytes += end - first;
  vk::Buffer& staging = appendStaging_[stagingUsed_++];
  if (staging.size() < bytes)  // kept: making pinned memory is slow
    staging =
        vk::Buffer::upload(*ctx_, 2 * bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, "tubes (staging)");
  std::vector<VkBufferCopy> regions;
  std::size_t at = 0;
  for (const auto& [first, end] : ranges) {
    if (end <= first) continue;
    std::memcpy(staging.mapped().data() + at, contents.data() + first, end - first);
    regions.push_back({at, first, end - first});
    at += end - first;
  }
  if (regions.empty()) return;
  vkCmdCopyBuffer(cmd, staging.handle(), buffer.handle(),
                  static_cast<std::uint32_t>(regions.size()), regions.data());
  vk::memoryBarrier(cmd, vk::access::kTransferWrite, vk::access::kAny);
}

void TubeRenderer::appendTubes(std::span<const shared::TubeSegment> added,
                               std::span<const shared::TubeSegment> all, float radius) {
  appendTimes_ = {};
  if (added.empty()) return;
  dropConsolidation();
  Stopwatch clock;
  const auto waitForTheFrame = [&] {
    Stopwatch waiting;
    waitForFrame();
    appendTimes_.frameWait += waiting.seconds();
    clock.restart();
  };
  const std::size_t first = segmentCount_, count = first + added.size();
  const bool compute = kernel_.backend == gpu::Backend::Compute;
  // A long run of appended structures makes every ray test many boxes: past a number, they are
  // made into one.
  const bool whole = radius != radius_ || count > 0xFFFFFF ||
                     (compute ? forest_.nodes().empty()
                              : !scene_ || scene_->blases.size() >= kMaxAppendedStructures);
  // compute's forest is host memory alone: a frame in flight may go on while it grows.
  if (!compute || whole) waitForTheFrame();
  if (whole || (compute && !forest_.append(added, radius))) {
    waitForTheFrame();
    setTubes(all, radius);
    appendTimes_.structures = clock.seconds();
    return;
  }
  for (const shared::TubeSegment& s : added) {
    tubesLower_ = glm::min(tubesLower_, glm::min(s.a, s.b) - radius);
    tubesUpper_ = glm::max(tubesUpper_, glm::max(s.a, s.b) + radius);
  }
  segmentCount_ = count;
  frames_ = 0;
  descriptorsStale_ = true;
  constexpr std::size_t kSegment = sizeof(shared::TubeSegment), kNode = sizeof(shared::TubeBvhNode);
  // The copies and builds of this append go to the device in one submission.
  vk::OneShotCommands commands(*ctx_);
  stagingUsed_ = 0;
  if (compute) {  // the forest rebuilt its last chunk on the host
    appendTimes_.structures = clock.seconds();
    waitForTheFrame();
    const std::pair<std::size_t, std::size_t> segmentRange{forest_.firstChangedSegment() * kSegment,
                                                           count * kSegment};
    writeRanges(segments_, "tube segments", std::as_bytes(std::span(forest_.segments())),
                std::span(&segmentRange, 1), commands.handle());
    const std::array<std::pair<std::size_t, std::size_t>, 2> nodeRanges{
        {{0, TubeForest::kTopNodes * kNode},
         {forest_.firstChangedNode() * kNode, forest_.nodes().size() * kNode}}};
    writeRanges(bvhNodes_, "tube BVH", std::as_bytes(std::span(forest_.nodes())), nodeRanges,
                commands.handle());
    appendTimes_.upload = clock.seconds();
    clock.restart();
    commands.submitAndWait();
    appendTimes_.device = clock.seconds();
    return;
  }
  deviceOrder_.insert(deviceOrder_.end(), added.begin(), added.end());
  const std::pair<std::size_t, std::size_t> addedRange{first * kSegment, count * kSegment};
  writeRanges(segments_, "tube segments", std::as_bytes(std::span(deviceOrder_)),
              std::span(&addedRange, 1), commands.handle());
  appendTimes_.upload = clock.seconds();
  clock.restart();
  // The new boxes' structure takes global ids from its first segment on (aabb_scene.hpp). Like
  // a binary counter, it first absorbs the structures before it that are at most twice its size,
  // so that they stay few (about log2 of the appends) and each segment is built into a structure
  // a few times over the appends, not at every one.
  std::vector<vk::AabbBlas>& blases = scene_->blases;
  std::size_t from = first;
  while (!blases.empty() && blases.back().boxCount <= 2 * (count - from)) {
    from = blases.back().firstBox;
    blases.pop_back();
  }
  const std::span<const shared::TubeSegment> rebuilt = std::span(deviceOrder_).subspan(from);
  for (vk::AabbBlas& blas : vk::recordAabbBlas(
           *ctx_, commands.handle(), segmentBoxes(rebuilt, radius), "tubes", appendBuild_)) {
    blas.firstBox += static_cast<std::uint32_t>(from);
    blases.push_back(std::move(blas));
  }
  appendTimes_.structures = clock.seconds();
  clock.restart();
  if (blases.size() > kMaxAppendedStructures) {  // split beyond the BLAS size limit
    commands.submitAndWait();
    setTubes(all, radius);
    appendTimes_.structures += clock.seconds();
    return;
  }
  if (!appendedTlas_) appendedTlas_.emplace(*ctx_, kMaxAppendedStructures, "appended tubes");
  appendedTlas_->record(commands.handle(), blases);
  appendTimes_.instances = clock.seconds();
  clock.restart();
  commands.submitAndWait();
  appendTimes_.device = clock.seconds();
  scene_->boxCount = static_cast<std::uint32_t>(count);
  appended_ = true;
}

void TubeRenderer::consolidateTubes(bool inBackground) {
  if (kernel_.backend == gpu::Backend::Compute) {
    if (consolidated_.valid()) {  // one is being built already
      if (!inBackground) adoptConsolidated(true);
      return;
    }
    if (forest_.chunks() <= 1) return;
    if (inBackground) {
      // forest_ stays as it is until the result is adopted or dropped (both wait for the task).
      // Making and filling buffers is free-threaded; recording and submitting are left to
      // adoptConsolidated, on this thread.
      consolidated_ = std::async(std::launch::async, [this, radius = radius_] {
        Consolidated whole;
        whole.forest.reset(forest_.segments(), radius);
        const auto staged = [&](auto items, const char* name) {
          const std::span<const std::byte> bytes = std::as_bytes(std::span(items));
          vk::Buffer buffer =
              vk::Buffer::upload(*ctx_, bytes.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT, name);
          std::memcpy(buffer.mapped().data(), bytes.data(), bytes.size());
          return buffer;
        };
        whole.segments = staged(whole.forest.segments(), "tube segments (staging)");
        whole.nodes = staged(whole.forest.nodes(), "tube BVH (staging)");
        return whole;
      });
      return;
    }
    const std::vector<shared::TubeSegment> segments = forest_.segments();
    return setTubes(segments, radius_);
  }
  if (!scene_ || scene_->blases.size() <= 1) return;
  waitForFrame();
  // The segments are on the device already, in deviceOrder_: only their structure is made again,
  // as one compacted BLAS (or as few as the size limit allows) under the same instance list.
  std::vector<vk::AabbBlas> blases =
      vk::buildAabbBlas(*ctx_, segmentBoxes(deviceOrder_, radius_), "tubes");
  if (blases.size() > kMaxAppendedStructures) {
    const std::vector<shared::TubeSegment> segments = std::move(deviceOrder_);
    return setTubes(segments, radius_);
  }
  scene_->blases = std::move(blases);
  appendedTlas_->build(scene_->blases);
  descriptorsStale_ = true;
}

std::size_t TubeRenderer::tubeStructures() const {
  if (kernel_.backend == gpu::Backend::Compute) return forest_.chunks();
  return scene_ ? scene_->blases.size() : 0;
}

void TubeRenderer::adoptConsolidated(bool wait) {
  if (!consolidated_.valid()) return;
  if (!wait && consolidated_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return;
  Consolidated whole = consolidated_.get();
  waitForFrame();
  constexpr VkBufferUsageFlags kTarget = kAppendable | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
  vk::Buffer segments =
      vk::Buffer::deviceLocal(*ctx_, whole.segments.size(), kTarget, "tube segments");
  vk::Buffer nodes = vk::Buffer::deviceLocal(*ctx_, whole.nodes.size(), kTarget, "tube BVH");
  vk::submitAndWait(*ctx_, [&](VkCommandBuffer cmd) {
    const VkBufferCopy segmentBytes{0, 0, whole.segments.size()},
        nodeBytes{0, 0, whole.nodes.size()};
    vkCmdCopyBuffer(cmd, whole.segments.handle(), segments.handle(), 1, &segmentBytes);
    vkCmdCopyBuffer(cmd, whole.nodes.handle(), nodes.handle(), 1, &nodeBytes);
    vk::memoryBarrier(cmd, vk::access::kTransferWrite, vk::access::kAny);
  });
  forest_ = std::move(whole.forest);
  segments_ = std::move(segments);
  bvhNodes_ = std::move(nodes);
  frames_ = 0;
  descriptorsStale_ = true;
}

void TubeRenderer::dropConsolidation() {
  if (!consolidated_.valid()) return;
  consolidated_.wait();
  consolidated_ = {};
}

void TubeRenderer::setColourMap(std::span<const glm::vec3> table) {
  if (table.size() < 2) throw std::invalid_argument("TubeRenderer: a colour map needs 2 entries");
  waitForFrame();
  colourMap_ = vk::uploadToDeviceLocal(*ctx_, table, kStorage, "colour map");
  frames_ = 0;
  descriptorsStale_ = true;
}

void TubeRenderer::resize(std::uint32_t width, std::uint32_t height) {
  if (width == 0 || height == 0)
    throw std::invalid_argument("TubeRenderer: the image needs at least one pixel");
  if (width == width_ && height == height_) return;
  waitForFrame();
  const VkDeviceSize pixelCount = VkDeviceSize(width) * height;
  accumulation_ =
      vk::Buffer::deviceLocal(*ctx_, pixelCount * sizeof(glm::vec4), kStorage, "accumulation");
  pixels_ = vk::Buffer::deviceLocal(*ctx_, pixelCount * 4,
                                    kStorage | VK_BUFFER_USAGE_TRANSFER_SRC_BIT, "pixels");
  width_ = width;
  height_ = height;
  frames_ = 0;
  descriptorsStale_ = true;
}

vk::DescriptorTarget TubeRenderer::tubeStructure() const {
  if (scene_)
    return vk::structureTarget(appended_ ? appendedTlas_->tlas().handle() : scene_->tlas.handle());
  return vk::storageTarget(bvhNodes_.handle() != VK_NULL_HANDLE ? bvhNodes_ : tree_);
}

void TubeRenderer::writeDescriptors() {
  vk::DescriptorWrites("render", AMRSTREAM_RENDER_BINDING_COUNT)
      .set(AMRSTREAM_BINDING_RENDER_PARAMS, vk::uniformTarget(params_))
      .set(AMRSTREAM_BINDING_RENDER_BRICKS, bricks_)
      .set(AMRSTREAM_BINDING_RENDER_SCALARS, scalars_)
      .set(AMRSTREAM_BINDING_RENDER_REGIONS, regions_)
      .set(AMRSTREAM_BINDING_RENDER_REGION_BRICKS, regionBricks_)
      .set(AMRSTREAM_BINDING_RENDER_REGION_TREE, tree_)
      .set(AMRSTREAM_BINDING_RENDER_SEGMENTS, segments_)
      .set(AMRSTREAM_BINDING_RENDER_COLOUR_MAP, colourMap_)
      .set(AMRSTREAM_BINDING_RENDER_ACCUMULATION, accumulation_)
      .set(AMRSTREAM_BINDING_RENDER_PIXELS, pixels_)
      .set(AMRSTREAM_BINDING_RENDER_TUBES, tubeStructure())
      .set(AMRSTREAM_BINDING_RENDER_SCALAR_GRADIENTS, scalarGradients_)
      .write(*ctx_, set_);
  descriptorsStale_ = false;
}

void TubeRenderer::submitFrame(const OrbitCamera& camera, const RenderSettings& settings) {
  if (width_ == 0) throw std::logic_error("TubeRenderer: resize() before renderFrame()");
  if (segmentCount_ > 0 && settings.tubeRadius != radius_)
    throw std::invalid_argument("TubeRenderer: the tubes were built for another radius");
  if (settings.volume && !hasScalars_)
    throw std::invalid_argument("TubeRenderer: the volume needs context scalars");
  waitForFrame();
  adoptConsolidated(false);
  if (lastCamera_ != camera || lastSettings_ != settings) frames_ = 0;
  lastCamera_ = camera;
  lastSettings_ = settings;

  const shared::RenderParams params =
      makeParams(camera, settings, *volume_, width_, height_, frames_, segmentCount_, linearVolume_,
                 tubesLower_, tubesUpper_);
  // The previous frame has completed, so the buffer is free to rewrite.
  std::memcpy(params_.mapped().data(), &params, sizeof(params));
  if (descriptorsStale_) writeDescriptors();

  frame_.submit([&](VkCommandBuffer cmd) {
    vkCmdBindPipeline(cmd, kernel_.bindPoint, kernel_.pipeline.get());
    vkCmdBindDescriptorSets(cmd, kernel_.bindPoint, kernel_.pipelineLayout.get(), 0, 1, &set_, 0,
                            nullptr);
    timer_.start(cmd);
    if (kernel_.backend == gpu::Backend::Pipeline) {
      const vk::ShaderBindingTable& sbt = kernel_.bindingTable;
      ctx_->functions().vkCmdTraceRaysKHR(cmd, &sbt.raygen, &sbt.miss, &sbt.hit, &sbt.callable,
                                          width_, height_, 1);
    } else {
      vkCmdDispatch(cmd, (width_ + kRenderTileSize - 1) / kRenderTileSize,
                    (height_ + kRenderTileSize - 1) / kRenderTileSize, 1);
    }
    timer_.stop(cmd);
    vk::memoryBarrier(cmd, vk::access::kAnyWrite, vk::access::kAny);
  });
  ++frames_;
}

void TubeRenderer::waitForFrame() const {
  if (!frame_.pending()) return;
  frame_.wait();
  lastFrameSeconds_ = timer_.seconds();
}

Image TubeRenderer::readImage() const {
  waitForFrame();
  Image image;
  image.width = width_;
  image.height = height_;
  const std::vector<std::byte> bytes = vk::readBack(*ctx_, pixels_);
  image.rgba.resize(bytes.size());
  std::memcpy(image.rgba.data(), bytes.data(), bytes.size());
  return image;
}

}  // namespace amrstream::render
