#pragma once
// The vector as dual cells (VolumeBuffers::dualValues), laid out on the device by
// shaders/glsl/build_dual_cells.comp from the compact values already there: the host uploads
// only each brick's first dual cell, not the 8 copies of every value.

#include <cstdint>
#include <span>

#include "vk/buffer.hpp"

namespace amrstream::gpu {

class DeviceUploader;

// A device-local buffer of `dualOffsets.back()` dual cells of 8 vec4 (128 bytes) each, with
// a device address: brick b's start at dual cell dualOffsets[b]. `bricks` and `values` are the
// VolumeBuffers of the same name. Complete on return.
vk::Buffer buildDualValues(const vk::Context& ctx, DeviceUploader& uploader,
                           const vk::Buffer& bricks, const vk::Buffer& values,
                           std::span<const std::uint64_t> dualOffsets);

}  // namespace amrstream::gpu
