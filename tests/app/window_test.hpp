#pragma once
// WindowTest: a fixture whose tests need a window (under xvfb-run in CTest). Like GpuTest, a test
// FAILS when no window or no presenting device is available, unless AMRSTREAM_SKIP_GPU_TESTS=1
// is set: then it is skipped with the reason.

#include <gtest/gtest.h>

#include <memory>
#include <optional>
#include <string>

#include "app/window.hpp"
#include "vk/context.hpp"

namespace amrstream::testing {

class WindowTest : public ::testing::Test {
 protected:
  void SetUp() override;
  void TearDown() override;

  app::Window& window() { return *window_; }
  // A validated context presenting to window(); kept so that TearDown() can check its log.
  vk::Context& buildPresentingContext();
  // Fails, or skips with AMRSTREAM_SKIP_GPU_TESTS=1, naming `problem`.
  void unavailable(const std::string& problem);

  std::optional<vk::Context> ctx_;

 private:
  std::optional<app::Window> window_;
  std::shared_ptr<const vk::ValidationLog> log_;
};

}  // namespace amrstream::testing
