#include "backend.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <array>

namespace amrstream::gpu {

namespace {
constexpr std::array<std::pair<Backend, std::string_view>, 4> kNames{{
    {Backend::RayQuery, "rayquery"},
    {Backend::Pipeline, "pipeline"},
    {Backend::Compute, "compute"},
    {Backend::Cpu, "cpu"},
}};
}  // namespace

std::string_view backendName(Backend backend) {
  for (const auto& [b, name] : kNames)
    if (b == backend) return name;
  return "unknown";
}

std::optional<Backend> parseBackend(std::string_view name) {
  for (const auto& [b, n] : kNames)
    if (n == name) return b;
  return std::nullopt;
}

vk::CapabilitySet requiredCapabilities(Backend backend) {
  switch (backend) {
    case Backend::RayQuery:
      return {vk::Capability::Compute, vk::Capability::RayQuery};
    case Backend::Pipeline:
      return {vk::Capability::Compute, vk::Capability::RayTracingPipeline};
    case Backend::Compute:
      return {vk::Capability::Compute};
    case Backend::Cpu:
      return {};
  }
  return {};
}

Backend chooseBackend(const vk::DeviceReport* device, std::string& why) {
  if (!device) {
    why = "no Vulkan device: using the CPU reference";
    return Backend::Cpu;
  }
  std::vector<std::string> skipped;
  for (Backend b : {Backend::RayQuery, Backend::Pipeline, Backend::Compute}) {
    const vk::CapabilitySet need = requiredCapabilities(b);
    if (device->supports(need)) {
      why = fmt::format("{} on {}", backendName(b), device->name);
      if (!skipped.empty()) why += fmt::format(" ({})", fmt::join(skipped, "; "));
      return b;
    }
    skipped.push_back(fmt::format("no {}: missing {}", backendName(b),
                                  fmt::join(device->missingFor(need), ", ")));
  }
  why = fmt::format("{} supports no GPU backend ({}): using the CPU reference", device->name,
                    fmt::join(skipped, "; "));
  return Backend::Cpu;
}

}  // namespace amrstream::gpu
