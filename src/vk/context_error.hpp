#pragma once
// Why no context could be made, in words a user can act on: the device, what it lacks and what
// to do ("NVIDIA H100 PCIe: missing VK_KHR_ray_query (datacenter GPUs expose no ray query; use
// --backend pipeline or compute)").

#include <stdexcept>

namespace amrstream::vk {

class ContextError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace amrstream::vk
