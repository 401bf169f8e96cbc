#pragma once
// A plain-data description of each Vulkan device and which capabilities it supports, for
// `amrstream devices`, for ContextBuilder's choice and for its error messages.

#include <vulkan/vulkan.h>

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "vk/capability.hpp"
#include "vk/device_support.hpp"

namespace amrstream::vk {

struct CapabilityStatus {
  Capability capability = Capability::Compute;
  // What the device lacks for this capability alone (see missingFor in device_support.hpp).
  std::vector<std::string> missing;

  bool supported() const { return missing.empty(); }
};

struct DeviceReport {
  uint32_t index = 0;  // in vkEnumeratePhysicalDevices order
  std::string name;
  VkPhysicalDeviceType type = VK_PHYSICAL_DEVICE_TYPE_OTHER;
  uint32_t vendorId = 0;
  VkDriverId driverId = static_cast<VkDriverId>(0);
  std::string driverName;  // empty where the device reports no driver properties
  std::string driverInfo;
  uint32_t apiVersion = 0;
  std::array<CapabilityStatus, kAllCapabilities.size()> capabilities;  // kAllCapabilities order

  const CapabilityStatus& status(Capability capability) const;
  bool supports(CapabilitySet required) const;
  // What is missing for all of `required` (implied capabilities added), each item once.
  std::vector<std::string> missingFor(CapabilitySet required) const;
};

DeviceReport makeReport(uint32_t index, const DeviceSupport& support,
                        const DeviceProperties& properties);

// One report per physical device, from an instance of its own without validation. Throws
// ContextError when there is no Vulkan loader/driver at all; an empty list means a driver
// loaded but offers no device.
std::vector<DeviceReport> listDevices();

// "discrete GPU", "integrated GPU", "virtual GPU", "CPU", "other".
std::string_view deviceTypeName(VkPhysicalDeviceType type);

// "[0] llvmpipe (LLVM 15.0.6, 256 bits) (CPU, llvmpipe Mesa 25.0.7, Vulkan 1.4.305)".
std::string describeDevice(const DeviceReport& report);

// Why `report` cannot serve `required`, with advice where the cause is known:
// "llvmpipe (LLVM 15.0.6, 256 bits): missing VK_KHR_ray_query (lavapipe older than Mesa 25.0
// has none: install mesa-vulkan-drivers from bookworm-backports)". Empty when it can.
std::string describeMissing(const DeviceReport& report, CapabilitySet required);

}  // namespace amrstream::vk
