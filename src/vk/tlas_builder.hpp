#pragma once
// TlasBuilder: rebuilds one TLAS over AabbBlases (the instances of aabb_scene.hpp) again and
// again in the same structure, instance buffer and scratch, made once for up to `capacity`
// instances: one submission a build and no allocation, for scenes that change every frame (the
// viewer's appended tubes). The TLAS's handle stays the same across builds.

#include <cstdint>
#include <span>
#include <string_view>
#include <utility>

#include "vk/aabb_scene.hpp"
#include "vk/acceleration_structure.hpp"
#include "vk/buffer.hpp"

namespace amrstream::vk {

class Context;

class TlasBuilder {
 public:
  // The context must outlive the builder.
  TlasBuilder(const Context& ctx, std::uint32_t capacity, std::string_view name);

  std::uint32_t capacity() const { return capacity_; }
  // Builds the TLAS over `blases` (at most capacity()); on return the build is complete and
  // visible to later commands on the context's queue. Throws std::length_error for more
  // instances than the capacity or a first box past 24 bits.
  const AccelerationStructure& build(std::span<const AabbBlas> blases);
  // The same build recorded into `cmd` (after anything recorded before it, such as the BLAS
  // builds): the instance list is written now, so nothing may use the TLAS from an earlier
  // submission until `cmd` has run.
  void record(VkCommandBuffer cmd, std::span<const AabbBlas> blases);
  const AccelerationStructure& tlas() const { return tlas_; }
  // The TLAS, to outlive the builder (buildTlas).
  AccelerationStructure takeTlas() && { return std::move(tlas_); }

 private:
  const Context* ctx_;
  std::uint32_t capacity_;
  Buffer instances_;  // host-visible: written by the host, read by the build
  VkAccelerationStructureBuildSizesInfoKHR sizes_;  // for `capacity` instances
  AccelerationStructure tlas_;
  ScratchBuffer scratch_;
};

}  // namespace amrstream::vk
