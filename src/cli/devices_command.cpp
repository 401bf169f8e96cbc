#include "devices_command.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "amrstream/backend.hpp"
#include "console.hpp"

namespace amrstream::cli {

namespace {

void runDevices() {
  const std::vector<DeviceDescription> devices = describeDevices();
  if (devices.empty()) printLine("no Vulkan devices: only the cpu backend is available");
  for (const DeviceDescription& d : devices) {
    printLine(
        fmt::format("{}: {} ({}, {} {})", d.index, d.name, d.type, d.driverName, d.driverInfo));
    for (const DeviceDescription::BackendSupport& b : d.backends)
      printLine(b.missing.empty() ? fmt::format("   {:<9} yes", b.backend)
                                  : fmt::format("   {:<9} no: missing {}", b.backend,
                                                fmt::join(b.missing, ", ")));
    printLine(fmt::format("   auto      -> {} for render and view, {} for trace{}", d.autoRender,
                          d.autoTrace,
                          d.software ? " (a software device: the CPU reference is faster)" : ""));
  }
}

}  // namespace

void addDevicesCommand(CLI::App& app) {
  app.add_subcommand("devices", "list the Vulkan devices and the backends each supports")
      ->callback(runDevices);
}

}  // namespace amrstream::cli
