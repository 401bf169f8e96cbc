#pragma once
// GpuTest: a fixture whose tests run on a validated Vulkan context (VK_LAYER_KHRONOS_validation
// with synchronization validation) and fail when the layer reported any error, including those
// raised while the context is destroyed (leaked objects).
//
// When no device offers the fixture's capabilities the test FAILS with ContextError's reason,
// unless AMRSTREAM_SKIP_GPU_TESTS=1 is set: then it is skipped with that reason.

#include <gtest/gtest.h>

#include <memory>
#include <optional>
#include <vector>

#include "vk/context.hpp"
#include "vk/device_report.hpp"

namespace amrstream::testing {

// True when AMRSTREAM_SKIP_GPU_TESTS=1: GPU tests skip instead of failing without a device.
bool gpuTestsOptedOut();

// The builder every GPU test uses: validation and synchronization validation on (the latter off
// in sanitizer builds: see tests/vk/CMakeLists.txt).
vk::ContextBuilder validatedBuilder(vk::CapabilitySet required);

class GpuTest : public ::testing::Test {
 protected:
  // What the context must support; override in derived fixtures.
  virtual vk::CapabilitySet required() const { return {vk::Capability::Compute}; }

  void SetUp() override;
  // Destroys the context (test-local Vulkan objects are gone by then) and expects no
  // validation errors.
  void TearDown() override;

  vk::Context& ctx() { return *ctx_; }

 private:
  std::optional<vk::Context> ctx_;
  std::shared_ptr<const vk::ValidationLog> log_;
};

// For tests about the devices themselves: listDevices(), failing (or skipping, as GpuTest does)
// when there is no Vulkan driver or no device.
class DeviceListTest : public ::testing::Test {
 protected:
  void SetUp() override;
  const std::vector<vk::DeviceReport>& devices() const { return devices_; }

 private:
  std::vector<vk::DeviceReport> devices_;
};

// Expects that `log` holds no errors, printing the first ones when it does.
void expectNoValidationErrors(const vk::ValidationLog& log);

}  // namespace amrstream::testing
