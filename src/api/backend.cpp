#include "amrstream/backend.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <optional>

#include "amrstream/error.hpp"
#include "api/device.hpp"
#include "gpu/backend.hpp"
#include "vk/context.hpp"
#include "vk/context_error.hpp"
#include "vk/device_report.hpp"

namespace amrstream {

namespace {

bool nameMatches(const std::string& name, const std::string& filter) {
  const auto lower = [](std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
    return s;
  };
  return lower(name).find(lower(filter)) != std::string::npos;
}

// The device `auto` uses: the requested one, else the first discrete GPU with a GPU backend,
// else the first device with one.
const vk::DeviceReport* autoDevice(const std::vector<vk::DeviceReport>& devices,
                                   const std::string& filter) {
  const vk::CapabilitySet compute = gpu::requiredCapabilities(gpu::Backend::Compute);
  const vk::DeviceReport* best = nullptr;
  for (const vk::DeviceReport& d : devices) {
    if (!filter.empty() && !nameMatches(d.name, filter)) continue;
    if (!d.supports(compute)) continue;
    if (d.type == VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU) return &d;
    if (!best) best = &d;
  }
  return best;
}

}  // namespace

BackendChoice chooseBackend(const BackendRequest& request, BackendUse use, const Log& log) {
  BackendChoice choice{gpu::Backend::Cpu, request.device};
  if (request.backend == "auto") {
    std::vector<vk::DeviceReport> devices;
    try {
      devices = vk::listDevices();
    } catch (const vk::ContextError& e) {
      say(log, fmt::format("backend    cpu: no Vulkan ({})", e.what()));
    }
    std::string why;
    const vk::DeviceReport* device = autoDevice(devices, request.device);
    if (use != BackendUse::Render && request.device.empty() && device &&
        device->type == VK_PHYSICAL_DEVICE_TYPE_CPU) {
      say(log, fmt::format("backend    auto: cpu ({} is a software Vulkan device, slower than the "
                           "CPU reference; name {{backend}} rayquery, pipeline or compute to {} "
                           "on it)",
                           device->name, use == BackendUse::Slice ? "make the LIC" : "trace"));
      return choice;
    }
    choice.backend = gpu::chooseBackend(device, why);
    if (device) choice.deviceFilter = device->name;
    if (use == BackendUse::Slice && device && choice.backend != gpu::Backend::Cpu) {
      choice.backend = gpu::Backend::Compute;
      why = fmt::format(
          "compute on {} (the LIC's one dispatch runs as fast on every backend, and "
          "compute sets up soonest; name {{backend}} to choose another)",
          device->name);
    }
    // autoDevice() gives only devices that run the compute backend.
    if (use == BackendUse::Render && device && device->type == VK_PHYSICAL_DEVICE_TYPE_CPU &&
        choice.backend != gpu::Backend::Compute) {
      choice.backend = gpu::Backend::Compute;
      why = fmt::format(
          "compute on {} (a software Vulkan device: its ray tracing is emulated, "
          "and the compute backend's own tube hierarchy renders about 9 times "
          "faster; name {{backend}} to choose another)",
          device->name);
    }
    say(log, "backend    auto: " + why);
  } else {
    const std::optional<gpu::Backend> named = gpu::parseBackend(request.backend);
    if (!named)
      throw settingError(
          "backend", "'" + request.backend + "' is not auto, rayquery, pipeline, compute or cpu");
    choice.backend = *named;
  }
  return choice;
}

vk::Context createContext(const BackendRequest& request, const BackendChoice& choice,
                          vk::CapabilitySet extra) {
  vk::ContextBuilder builder;
  builder.require(gpu::requiredCapabilities(choice.backend))
      .require(extra)
      .validation(request.validation);
  if (!choice.deviceFilter.empty()) builder.deviceName(choice.deviceFilter);
  builder.deviceSlot(request.deviceSlot);
  return builder.build();
}

void checkValidation(const vk::Context& ctx) {
  if (ctx.validationErrorCount() > 0)
    throw std::runtime_error(
        fmt::format("the Vulkan validation layer reported {} errors", ctx.validationErrorCount()));
}

std::vector<DeviceDescription> describeDevices() {
  std::vector<DeviceDescription> described;
  for (const vk::DeviceReport& d : vk::listDevices()) {
    DeviceDescription out;
    out.index = d.index;
    out.name = d.name;
    out.type = vk::deviceTypeName(d.type);
    out.driverName = d.driverName;
    out.driverInfo = d.driverInfo;
    for (gpu::Backend b : {gpu::Backend::RayQuery, gpu::Backend::Pipeline, gpu::Backend::Compute})
      out.backends.push_back(
          {std::string(gpu::backendName(b)), d.missingFor(gpu::requiredCapabilities(b))});
    std::string why;
    const gpu::Backend best = gpu::chooseBackend(&d, why);
    out.software = d.type == VK_PHYSICAL_DEVICE_TYPE_CPU;
    const bool compute = d.supports(gpu::requiredCapabilities(gpu::Backend::Compute));
    out.autoRender = gpu::backendName(out.software && compute ? gpu::Backend::Compute : best);
    out.autoTrace = out.software ? "cpu" : out.autoRender;
    described.push_back(std::move(out));
  }
  return described;
}

bool validationRequested() {
  const char* setting = std::getenv("AMRSTREAM_VALIDATION");
#ifdef NDEBUG
  return setting && std::string(setting) == "1";
#else
  return !(setting && std::string(setting) == "0");
#endif
}

}  // namespace amrstream
