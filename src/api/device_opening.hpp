#pragma once
// A tracing backend's Vulkan device, opened on a thread of its own while the input is read and
// the volume is built: creating an instance and a device takes 0.15 s on an H100 host, and
// nothing before the upload needs them.

#include <future>
#include <optional>
#include <string>
#include <vector>

#include "amrstream/backend.hpp"
#include "amrstream/log.hpp"
#include "api/device.hpp"
#include "vk/context.hpp"

namespace amrstream {

class DeviceOpening {
 public:
  struct Opened {
    BackendChoice choice;
    std::optional<vk::Context> ctx;  // none for the CPU reference
    std::vector<std::string> lines;  // what choosing said, said again when taken
  };

  // Starts choosing the backend for tracing (chooseBackend) and creating its context.
  explicit DeviceOpening(BackendRequest request);
  // Waits for it (until it ends, should it not have been taken).
  ~DeviceOpening();
  DeviceOpening(const DeviceOpening&) = delete;
  DeviceOpening& operator=(const DeviceOpening&) = delete;

  // The backend and its context, saying on `log` what choosing said; rethrows what choosing or
  // creating threw. Once only.
  Opened take(const Log& log);

 private:
  std::future<Opened> opening_;
};

}  // namespace amrstream
