#include "vk/capability.hpp"

#include <vulkan/vulkan.h>

namespace amrstream::vk {

std::string_view capabilityName(Capability capability) {
  switch (capability) {
    case Capability::Compute:
      return "compute";
    case Capability::AccelerationStructure:
      return "acceleration structure";
    case Capability::RayQuery:
      return "ray query";
    case Capability::RayTracingPipeline:
      return "ray tracing pipeline";
  }
  return "unknown capability";
}

std::string CapabilitySet::toString() const {
  std::string text;
  for (Capability c : kAllCapabilities) {
    if (!contains(c)) continue;
    if (!text.empty()) text += ", ";
    text += capabilityName(c);
  }
  return text.empty() ? "nothing" : text;
}

std::string_view featureName(Feature feature) {
  switch (feature) {
    case Feature::ScalarBlockLayout:
      return "scalarBlockLayout";
    case Feature::BufferDeviceAddress:
      return "bufferDeviceAddress";
    case Feature::AccelerationStructure:
      return "accelerationStructure";
    case Feature::RayQuery:
      return "rayQuery";
    case Feature::RayTracingPipeline:
      return "rayTracingPipeline";
  }
  return "unknown feature";
}

Requirements requirementsOf(Capability capability) {
  switch (capability) {
    case Capability::Compute:
      // Host/device structs use layout(scalar) so that glm's layout matches
      // (docs/architecture.md, "GPU kernels").
      return {{}, {Feature::ScalarBlockLayout}};
    case Capability::AccelerationStructure:
      // VK_KHR_acceleration_structure requires VK_KHR_deferred_host_operations even when no
      // build is deferred, and builds read their inputs through buffer device addresses.
      return {{VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME,
               VK_KHR_DEFERRED_HOST_OPERATIONS_EXTENSION_NAME},
              {Feature::AccelerationStructure, Feature::BufferDeviceAddress}};
    case Capability::RayQuery:
      return {{VK_KHR_RAY_QUERY_EXTENSION_NAME}, {Feature::RayQuery}};
    case Capability::RayTracingPipeline:
      return {{VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME}, {Feature::RayTracingPipeline}};
  }
  return {};
}

}  // namespace amrstream::vk
