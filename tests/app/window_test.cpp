#include "window_test.hpp"

#include <cstdlib>

#include "app/window_error.hpp"
#include "gpu_test.hpp"

namespace amrstream::testing {

void WindowTest::unavailable(const std::string& problem) {
  if (gpuTestsOptedOut()) GTEST_SKIP() << "AMRSTREAM_SKIP_GPU_TESTS=1: " << problem;
  std::string hint = "(set AMRSTREAM_SKIP_GPU_TESTS=1 to skip GPU tests)";
  if (std::getenv("AMRSTREAM_XVFB_RUN_MISSING") != nullptr) {
    hint =
        "(xvfb-run was not found when CMake configured the build: apt-get install xvfb xauth "
        "and reconfigure, or set AMRSTREAM_SKIP_GPU_TESTS=1)";
  }
  FAIL() << problem << "\n" << hint;
}

void WindowTest::SetUp() {
  try {
    window_.emplace(app::WindowOptions{320, 240, "amrstream test", true});
  } catch (const app::WindowError& error) {
    unavailable(error.what());
  }
}

vk::Context& WindowTest::buildPresentingContext() {
  ctx_.emplace(validatedBuilder({vk::Capability::Compute})
                   .presentation(window_->requiredInstanceExtensions(), window_->surfaceFactory())
                   .build());
  log_ = ctx_->validationLog();
  return *ctx_;
}

void WindowTest::TearDown() {
  ctx_.reset();
  if (log_) expectNoValidationErrors(*log_);
  window_.reset();
}

}  // namespace amrstream::testing
