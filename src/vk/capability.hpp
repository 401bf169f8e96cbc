#pragma once
// What a context can do, as the backends of docs/backends.md need it. A CapabilitySet is what
// a caller asks ContextBuilder for; requirementsOf() says which Vulkan extensions and features
// each capability stands for, so device probing, the device report and device creation all read
// one list.

#include <array>
#include <cstdint>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace amrstream::vk {

enum class Capability : uint8_t {
  Compute,  // Vulkan 1.2, a compute queue, scalar block layout
  // VK_KHR_acceleration_structure (+ buffer device address). No build is valid unless ray
  // query or ray tracing pipelines are enabled too, so a context asked for this alone also
  // enables whichever of the two the device has.
  AccelerationStructure,
  RayQuery,            // VK_KHR_ray_query (implies AccelerationStructure)
  RayTracingPipeline,  // VK_KHR_ray_tracing_pipeline (implies AccelerationStructure)
};

inline constexpr std::array<Capability, 4> kAllCapabilities = {
    Capability::Compute, Capability::AccelerationStructure, Capability::RayQuery,
    Capability::RayTracingPipeline};

// "compute", "acceleration structure", "ray query", "ray tracing pipeline".
std::string_view capabilityName(Capability capability);

class CapabilitySet {
 public:
  constexpr CapabilitySet() = default;
  constexpr CapabilitySet(std::initializer_list<Capability> capabilities) {
    for (Capability c : capabilities) insert(c);
  }

  constexpr CapabilitySet& insert(Capability c) {
    bits_ |= bit(c);
    return *this;
  }
  constexpr CapabilitySet& insert(CapabilitySet other) {
    bits_ |= other.bits_;
    return *this;
  }
  constexpr bool contains(Capability c) const { return (bits_ & bit(c)) != 0; }
  constexpr bool containsAll(CapabilitySet other) const {
    return (bits_ & other.bits_) == other.bits_;
  }
  constexpr bool operator==(const CapabilitySet&) const = default;

  // With what the others need added: Compute always, AccelerationStructure for ray query and
  // ray tracing pipelines (both extensions require it).
  constexpr CapabilitySet withImplied() const {
    CapabilitySet result = *this;
    result.insert(Capability::Compute);
    if (contains(Capability::RayQuery) || contains(Capability::RayTracingPipeline)) {
      result.insert(Capability::AccelerationStructure);
    }
    return result;
  }

  // "compute, ray query", in the order of kAllCapabilities.
  std::string toString() const;

 private:
  static constexpr uint8_t bit(Capability c) { return uint8_t(1u << static_cast<unsigned>(c)); }
  uint8_t bits_ = 0;
};

// A device feature bit that a capability needs, named as in the specification.
enum class Feature : uint8_t {
  ScalarBlockLayout,
  BufferDeviceAddress,
  AccelerationStructure,
  RayQuery,
  RayTracingPipeline,
};

// "scalarBlockLayout" etc.
std::string_view featureName(Feature feature);

struct Requirements {
  std::vector<const char*> extensions;
  std::vector<Feature> features;
};

// What one capability needs beyond Vulkan 1.2 and a compute queue (which every capability needs).
// Extension dependencies promoted to core 1.2 (buffer device address, descriptor indexing,
// SPIR-V 1.4, shader float controls) are not listed: the context requests API 1.2.
Requirements requirementsOf(Capability capability);

}  // namespace amrstream::vk
