#include <gtest/gtest.h>

#include "vk/presentation.hpp"

namespace amrstream::testing {
namespace {

TEST(PresentationSupport, NamesWhatIsMissing) {
  vk::PresentationSupport none;
  const auto missing = none.missing();
  ASSERT_EQ(missing.size(), 2u);
  EXPECT_EQ(missing[0], "VK_KHR_swapchain");
  EXPECT_EQ(missing[1], "a queue family with graphics, compute and presentation to the window");

  const vk::PresentationSupport all{true, 0u};
  EXPECT_TRUE(all.missing().empty());
}

}  // namespace
}  // namespace amrstream::testing
