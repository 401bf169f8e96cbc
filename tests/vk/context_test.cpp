#include "vk/context.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <ostream>
#include <string>

#include "gpu_test.hpp"
#include "vk/device_report.hpp"
#include "vk/vk_error.hpp"

namespace amrstream::vk {
// Readable test names for parameters.
void PrintTo(const CapabilitySet& set, std::ostream* os) { *os << set.toString(); }
}  // namespace amrstream::vk

namespace amrstream::testing {
namespace {

using vk::Capability;
using vk::CapabilitySet;

bool isPowerOfTwo(uint64_t value) { return value != 0 && (value & (value - 1)) == 0; }

class ContextCapabilities : public GpuTest, public ::testing::WithParamInterface<CapabilitySet> {
 protected:
  CapabilitySet required() const override { return GetParam(); }
};

TEST_P(ContextCapabilities, BuildsWithSaneProperties) {
  vk::Context& c = ctx();
  const CapabilitySet expected = GetParam().withImplied();
  EXPECT_TRUE(c.capabilities().containsAll(expected));
  if (expected.contains(Capability::AccelerationStructure)) {
    // Acceleration structures alone bring one way to traverse them (ray query on lavapipe).
    EXPECT_TRUE(c.has(Capability::RayQuery) || c.has(Capability::RayTracingPipeline));
  } else {
    EXPECT_EQ(c.capabilities(), expected);
  }
  EXPECT_TRUE(c.validationEnabled());
  EXPECT_TRUE(c.debugUtilsEnabled());
  EXPECT_NE(c.device(), VK_NULL_HANDLE);
  EXPECT_NE(c.queue(), VK_NULL_HANDLE);
  EXPECT_NE(c.commandPool(), VK_NULL_HANDLE);
  EXPECT_FALSE(c.deviceName().empty());
  EXPECT_GE(c.properties().apiVersion, VK_API_VERSION_1_2);
  EXPECT_GE(c.limits().maxComputeWorkGroupInvocations, 128u);  // the specification's minimum
  EXPECT_GE(c.limits().maxStorageBufferRange, 1u << 27);       // 128 MiB on llvmpipe
  EXPECT_TRUE(c.bufferDeviceAddressEnabled());
  const std::vector<VkDeviceSize> heaps = c.memoryHeapSizes();
  ASSERT_FALSE(heaps.empty());
  EXPECT_GT(*std::max_element(heaps.begin(), heaps.end()), 0u);

  const auto& as = c.accelerationStructureProperties();
  const auto& rt = c.rayTracingPipelineProperties();
  if (expected.contains(Capability::AccelerationStructure)) {
    EXPECT_GT(as.maxPrimitiveCount, 0u);
    EXPECT_GT(as.maxGeometryCount, 0u);
    EXPECT_GT(as.maxInstanceCount, 0u);
    EXPECT_TRUE(isPowerOfTwo(as.minAccelerationStructureScratchOffsetAlignment));
  } else {
    EXPECT_EQ(as.maxPrimitiveCount, 0u);
  }
  if (c.has(Capability::RayTracingPipeline)) {
    EXPECT_GT(rt.shaderGroupHandleSize, 0u);
    EXPECT_TRUE(isPowerOfTwo(rt.shaderGroupBaseAlignment));
    EXPECT_TRUE(isPowerOfTwo(rt.shaderGroupHandleAlignment));
    EXPECT_GE(rt.maxRayRecursionDepth, 1u);
  } else {
    EXPECT_EQ(rt.shaderGroupHandleSize, 0u);
  }

  // Exactly the entry points of the enabled extensions are loaded.
  const vk::DeviceFunctions& f = c.functions();
  EXPECT_EQ(bool(f.vkCmdBuildAccelerationStructuresKHR),
            expected.contains(Capability::AccelerationStructure));
  EXPECT_EQ(bool(f.vkCmdCopyAccelerationStructureKHR),
            expected.contains(Capability::AccelerationStructure));
  EXPECT_EQ(bool(f.vkCmdTraceRaysKHR), c.has(Capability::RayTracingPipeline));
  EXPECT_EQ(bool(f.vkCreateRayTracingPipelinesKHR), c.has(Capability::RayTracingPipeline));
  EXPECT_TRUE(c.instanceFunctions().vkSetDebugUtilsObjectNameEXT);
}

INSTANTIATE_TEST_SUITE_P(Lavapipe, ContextCapabilities,
                         ::testing::Values(CapabilitySet{Capability::Compute},
                                           CapabilitySet{Capability::AccelerationStructure},
                                           CapabilitySet{Capability::RayQuery},
                                           CapabilitySet{Capability::RayTracingPipeline},
                                           CapabilitySet{Capability::RayQuery,
                                                         Capability::RayTracingPipeline}),
                         [](const ::testing::TestParamInfo<CapabilitySet>& info) {
                           std::string name = info.param.toString();
                           std::erase_if(name, [](char ch) { return ch == ' ' || ch == ','; });
                           return name;
                         });

using ComputeContext = GpuTest;

TEST_F(ComputeContext, CallingAnUnloadedFunctionThrowsNamingTheExtension) {
  try {
    ctx().functions().vkCmdTraceRaysKHR(VK_NULL_HANDLE, nullptr, nullptr, nullptr, nullptr, 1, 1,
                                        1);
    FAIL() << "expected a VulkanError";
  } catch (const vk::VulkanError& error) {
    EXPECT_EQ(error.result(), VK_ERROR_EXTENSION_NOT_PRESENT);
    EXPECT_NE(std::string(error.what()).find("vkCmdTraceRaysKHR"), std::string::npos);
    EXPECT_NE(std::string(error.what()).find("VK_KHR_ray_tracing_pipeline"), std::string::npos);
  }
}

TEST_F(ComputeContext, MovesKeepTheDeviceAndCountErrorsInOneLog) {
  vk::Context moved = std::move(ctx());
  EXPECT_NE(moved.device(), VK_NULL_HANDLE);
  EXPECT_EQ(ctx().device(), VK_NULL_HANDLE);
  EXPECT_EQ(moved.validationErrorCount(), 0u);
}

using ContextBuilderErrors = DeviceListTest;

TEST_F(ContextBuilderErrors, NameFilterMatchingNothingListsTheDevicesSeen) {
  try {
    validatedBuilder({Capability::Compute}).deviceName("no-such-gpu-9000").build();
    FAIL() << "expected a ContextError";
  } catch (const vk::ContextError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("no Vulkan device name contains 'no-such-gpu-9000'; devices seen:"),
              std::string::npos)
        << message;
    for (const vk::DeviceReport& device : devices()) {
      EXPECT_NE(message.find(vk::describeDevice(device)), std::string::npos) << message;
    }
  }
}

TEST_F(ContextBuilderErrors, IndexOutOfRangeListsTheDevicesSeen) {
  try {
    validatedBuilder({Capability::Compute}).deviceIndex(1000).build();
    FAIL() << "expected a ContextError";
  } catch (const vk::ContextError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("no Vulkan device has index 1000; devices seen:"), std::string::npos)
        << message;
    EXPECT_NE(message.find(devices().front().name), std::string::npos) << message;
  }
}

TEST_F(ContextBuilderErrors, NameFilterIsCaseInsensitive) {
  std::string upper = devices().front().name;
  std::transform(upper.begin(), upper.end(), upper.begin(), ::toupper);
  const vk::Context c = vk::ContextBuilder().deviceName(upper).build();
  EXPECT_EQ(c.deviceName(), devices().front().name);
}

}  // namespace
}  // namespace amrstream::testing
