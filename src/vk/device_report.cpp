#include "vk/device_report.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "vk/instance.hpp"

namespace amrstream::vk {
namespace {

constexpr uint32_t kNvidiaVendorId = 0x10DE;

bool contains(const std::vector<std::string>& items, std::string_view item) {
  return std::find(items.begin(), items.end(), item) != items.end();
}

// Advice for the causes we know; empty when there is nothing useful to say.
std::string adviceFor(const DeviceReport& report, const std::vector<std::string>& missing) {
  const bool lacksRayTracingExtension =
      contains(missing, VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME) ||
      contains(missing, VK_KHR_RAY_QUERY_EXTENSION_NAME) ||
      contains(missing, VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME);
  if (report.driverId == VK_DRIVER_ID_MESA_LLVMPIPE && lacksRayTracingExtension) {
    return "lavapipe older than Mesa 25.0 has none: install mesa-vulkan-drivers from "
           "bookworm-backports";
  }
  if (report.vendorId == kNvidiaVendorId && missing.size() == 1 &&
      missing.front() == VK_KHR_RAY_QUERY_EXTENSION_NAME) {
    return "datacenter GPUs expose no ray query; use --backend pipeline or compute";
  }
  if (report.apiVersion < kRequiredApiVersion) return "update the driver";
  return {};
}

}  // namespace

const CapabilityStatus& DeviceReport::status(Capability capability) const {
  return capabilities[static_cast<size_t>(capability)];
}

bool DeviceReport::supports(CapabilitySet required) const { return missingFor(required).empty(); }

std::vector<std::string> DeviceReport::missingFor(CapabilitySet required) const {
  std::vector<std::string> missing;
  const CapabilitySet all = required.withImplied();
  for (const CapabilityStatus& s : capabilities) {
    if (!all.contains(s.capability)) continue;
    for (const std::string& item : s.missing) {
      if (!contains(missing, item)) missing.push_back(item);
    }
  }
  return missing;
}

DeviceReport makeReport(uint32_t index, const DeviceSupport& support,
                        const DeviceProperties& properties) {
  DeviceReport report;
  report.index = index;
  report.name = properties.core.deviceName;
  report.type = properties.core.deviceType;
  report.vendorId = properties.core.vendorID;
  report.driverId = properties.driver.driverID;
  report.driverName = properties.driver.driverName;
  report.driverInfo = properties.driver.driverInfo;
  report.apiVersion = properties.core.apiVersion;
  for (size_t i = 0; i < kAllCapabilities.size(); ++i) {
    report.capabilities[i].capability = kAllCapabilities[i];
    report.capabilities[i].missing = vk::missingFor(support, kAllCapabilities[i]);
  }
  return report;
}

std::vector<DeviceReport> listDevices() {
  const Instance instance = createInstance({});
  std::vector<DeviceReport> reports;
  const auto devices = enumeratePhysicalDevices(instance.handle.get());
  for (uint32_t i = 0; i < devices.size(); ++i) {
    const DeviceSupport support = probeSupport(devices[i]);
    reports.push_back(makeReport(i, support, queryProperties(devices[i], support)));
  }
  return reports;
}

std::string_view deviceTypeName(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
      return "discrete GPU";
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
      return "integrated GPU";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
      return "virtual GPU";
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
      return "CPU";
    default:
      return "other";
  }
}

std::string describeDevice(const DeviceReport& report) {
  std::string driver = report.driverName;
  if (!report.driverInfo.empty()) driver += (driver.empty() ? "" : " ") + report.driverInfo;
  return fmt::format("[{}] {} ({}, {}Vulkan {})", report.index, report.name,
                     deviceTypeName(report.type), driver.empty() ? "" : driver + ", ",
                     formatApiVersion(report.apiVersion));
}

std::string describeMissing(const DeviceReport& report, CapabilitySet required) {
  const std::vector<std::string> missing = report.missingFor(required);
  if (missing.empty()) return {};
  std::string text = fmt::format("{}: missing {}", report.name, fmt::join(missing, ", "));
  const std::string advice = adviceFor(report, missing);
  if (!advice.empty()) text += fmt::format(" ({})", advice);
  return text;
}

}  // namespace amrstream::vk
