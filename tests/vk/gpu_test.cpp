#include "gpu_test.hpp"

#include <cstdlib>
#include <string>
#include <string_view>

namespace amrstream::testing {

bool gpuTestsOptedOut() {
  const char* value = std::getenv("AMRSTREAM_SKIP_GPU_TESTS");
  return value != nullptr && std::string_view(value) == "1";
}

vk::ContextBuilder validatedBuilder(vk::CapabilitySet required) {
  vk::ContextBuilder builder;
  builder.require(required).validation(true);
#ifndef AMRSTREAM_GPU_TESTS_WITHOUT_SYNC_VALIDATION
  builder.synchronizationValidation(true);
#endif
  return builder;
}

void GpuTest::SetUp() {
  try {
    ctx_.emplace(validatedBuilder(required()).build());
    log_ = ctx_->validationLog();
  } catch (const vk::ContextError& error) {
    if (gpuTestsOptedOut()) GTEST_SKIP() << "AMRSTREAM_SKIP_GPU_TESTS=1: " << error.what();
    FAIL() << "no Vulkan device for " << required().withImplied().toString() << ": " << error.what()
           << "\n(set AMRSTREAM_SKIP_GPU_TESTS=1 to skip GPU tests)";
  }
}

void GpuTest::TearDown() {
  ctx_.reset();
  if (log_) expectNoValidationErrors(*log_);
}

void DeviceListTest::SetUp() {
  std::string problem;
  try {
    devices_ = vk::listDevices();
    if (devices_.empty()) problem = "the Vulkan driver offers no device";
  } catch (const vk::ContextError& error) {
    problem = error.what();
  }
  if (problem.empty()) return;
  if (gpuTestsOptedOut()) GTEST_SKIP() << "AMRSTREAM_SKIP_GPU_TESTS=1: " << problem;
  FAIL() << problem << "\n(set AMRSTREAM_SKIP_GPU_TESTS=1 to skip GPU tests)";
}

void expectNoValidationErrors(const vk::ValidationLog& log) {
  std::string first;
  for (const std::string& message : log.errors()) first += "\n  " + message;
  EXPECT_EQ(log.errorCount(), 0u) << "validation errors:" << first;
}

}  // namespace amrstream::testing
