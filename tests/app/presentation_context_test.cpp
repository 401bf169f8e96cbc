// ContextBuilder::presentation(): the surface, the queue and the errors.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "app/frame_presenter.hpp"
#include "gpu_test.hpp"
#include "vk/context.hpp"
#include "window_test.hpp"

namespace amrstream::testing {
namespace {

using PresentationContextTest = WindowTest;

TEST_F(PresentationContextTest, OwnsTheSurfaceAndOneQueueForGraphicsComputeAndPresentation) {
  vk::Context& ctx = buildPresentingContext();
  EXPECT_TRUE(ctx.presentationEnabled());
  ASSERT_NE(ctx.surface(), VK_NULL_HANDLE);

  uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(ctx.physicalDevice(), &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(ctx.physicalDevice(), &count, families.data());
  ASSERT_LT(ctx.queueFamilyIndex(), count);
  const VkQueueFlags flags = families[ctx.queueFamilyIndex()].queueFlags;
  EXPECT_NE(flags & VK_QUEUE_GRAPHICS_BIT, 0u);
  EXPECT_NE(flags & VK_QUEUE_COMPUTE_BIT, 0u);
  VkBool32 presents = VK_FALSE;
  ASSERT_EQ(vkGetPhysicalDeviceSurfaceSupportKHR(ctx.physicalDevice(), ctx.queueFamilyIndex(),
                                                 ctx.surface(), &presents),
            VK_SUCCESS);
  EXPECT_EQ(presents, VK_TRUE);
  // The capabilities asked for are unchanged by presentation.
  EXPECT_EQ(ctx.capabilities(), vk::CapabilitySet{vk::Capability::Compute});
}

TEST_F(PresentationContextTest, HeadlessContextHasNoSurface) {
  ctx_.emplace(validatedBuilder({vk::Capability::Compute}).build());
  EXPECT_FALSE(ctx_->presentationEnabled());
  EXPECT_EQ(ctx_->surface(), VK_NULL_HANDLE);
  EXPECT_THROW(app::FramePresenter(*ctx_, window()), vk::ContextError);
  EXPECT_EQ(ctx_->validationErrorCount(), 0u);
}

TEST_F(PresentationContextTest, MissingInstanceExtensionIsNamed) {
  std::vector<std::string> extensions = window().requiredInstanceExtensions();
  extensions.push_back("VK_KHR_no_such_surface");
  try {
    validatedBuilder({vk::Capability::Compute})
        .presentation(extensions, window().surfaceFactory())
        .build();
    FAIL() << "a context was built with an unknown instance extension";
  } catch (const vk::ContextError& error) {
    EXPECT_NE(std::string(error.what()).find("VK_KHR_no_such_surface"), std::string::npos)
        << error.what();
  }
}

TEST_F(PresentationContextTest, SurfaceFactoryErrorsReachTheCaller) {
  auto builder = validatedBuilder({vk::Capability::Compute});
  builder.presentation(window().requiredInstanceExtensions(),
                       [](VkInstance) -> VkSurfaceKHR { throw std::runtime_error("no surface"); });
  EXPECT_THROW(builder.build(), std::runtime_error);
  builder.presentation(window().requiredInstanceExtensions(),
                       [](VkInstance) { return VkSurfaceKHR(VK_NULL_HANDLE); });
  EXPECT_THROW(builder.build(), vk::ContextError);
}

}  // namespace
}  // namespace amrstream::testing
