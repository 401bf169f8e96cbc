#include "devices_command.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "gpu/backend.hpp"
#include "vk/device_report.hpp"

namespace amrstream::cli {

namespace {

void runDevices() {
  const std::vector<vk::DeviceReport> devices = vk::listDevices();
  if (devices.empty()) fmt::print("no Vulkan devices: only the cpu backend is available\n");
  for (const vk::DeviceReport& d : devices) {
    fmt::print("{}: {} ({}, {} {})\n", d.index, d.name, vk::deviceTypeName(d.type), d.driverName,
               d.driverInfo);
    for (gpu::Backend b : {gpu::Backend::RayQuery, gpu::Backend::Pipeline, gpu::Backend::Compute}) {
      const vk::CapabilitySet need = gpu::requiredCapabilities(b);
      if (d.supports(need))
        fmt::print("   {:<9} yes\n", gpu::backendName(b));
      else
        fmt::print("   {:<9} no: missing {}\n", gpu::backendName(b),
                   fmt::join(d.missingFor(need), ", "));
    }
    std::string why;
    const gpu::Backend best = gpu::chooseBackend(&d, why);
    // Tracing on a software device is slower than the CPU reference (amrstream/backend.hpp).
    const bool software = d.type == VK_PHYSICAL_DEVICE_TYPE_CPU;
    fmt::print("   auto      -> {} for render and view, {} for trace{}\n", gpu::backendName(best),
               software ? "cpu" : gpu::backendName(best),
               software ? " (a software device: the CPU reference is faster)" : "");
  }
}

}  // namespace

void addDevicesCommand(CLI::App& app) {
  app.add_subcommand("devices", "list the Vulkan devices and the backends each supports")
      ->callback(runDevices);
}

}  // namespace amrstream::cli
