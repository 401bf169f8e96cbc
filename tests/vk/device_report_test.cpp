#include "vk/device_report.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "gpu_test.hpp"
#include "vk/context.hpp"
#include "vk/instance.hpp"

namespace amrstream::testing {
namespace {

using vk::Capability;
using vk::CapabilitySet;

using ListDevices = DeviceListTest;

TEST_F(ListDevices, ReportsLlvmpipeWithAllFourCapabilities) {
  const auto llvmpipe = std::find_if(devices().begin(), devices().end(), [](const auto& d) {
    return d.driverId == VK_DRIVER_ID_MESA_LLVMPIPE;
  });
  if (llvmpipe == devices().end()) {
    if (gpuTestsOptedOut()) GTEST_SKIP() << "no llvmpipe device";
    FAIL() << "no llvmpipe device (install mesa-vulkan-drivers from bookworm-backports)";
  }
  EXPECT_NE(llvmpipe->name.find("llvmpipe"), std::string::npos);
  EXPECT_EQ(llvmpipe->type, VK_PHYSICAL_DEVICE_TYPE_CPU);
  EXPECT_EQ(llvmpipe->driverName, "llvmpipe");
  EXPECT_NE(llvmpipe->driverInfo.find("Mesa"), std::string::npos);
  EXPECT_GE(llvmpipe->apiVersion, VK_API_VERSION_1_2);
  for (Capability c : vk::kAllCapabilities) {
    EXPECT_TRUE(llvmpipe->status(c).supported())
        << vk::capabilityName(c) << ": " << vk::describeMissing(*llvmpipe, {c});
  }
  EXPECT_TRUE(llvmpipe->supports({Capability::RayQuery, Capability::RayTracingPipeline}));
  EXPECT_EQ(vk::describeMissing(*llvmpipe, {Capability::RayQuery}), "");
  EXPECT_NE(vk::describeDevice(*llvmpipe).find("(CPU, llvmpipe Mesa"), std::string::npos)
      << vk::describeDevice(*llvmpipe);
}

// A real device's support with ray query taken away: what bookworm's own lavapipe (Mesa 22.3)
// looks like to the requirement check.
using DeviceReportOnLavapipe = DeviceListTest;

TEST_F(DeviceReportOnLavapipe, WithoutRayQueryItGetsTheBackportsAdvice) {
  const vk::Instance instance = vk::createInstance({});
  const auto devices = vk::enumeratePhysicalDevices(instance.handle.get());
  for (uint32_t i = 0; i < devices.size(); ++i) {
    vk::DeviceSupport support = vk::probeSupport(devices[i]);
    const vk::DeviceProperties properties = vk::queryProperties(devices[i], support);
    if (properties.driver.driverID != VK_DRIVER_ID_MESA_LLVMPIPE) continue;
    std::erase(support.extensions, std::string(VK_KHR_RAY_QUERY_EXTENSION_NAME));
    support.rayQuery = false;

    const vk::DeviceReport report = vk::makeReport(i, support, properties);
    EXPECT_TRUE(report.supports({Capability::RayTracingPipeline}));
    EXPECT_FALSE(report.supports({Capability::RayQuery}));
    EXPECT_EQ(report.status(Capability::RayQuery).missing,
              std::vector<std::string>{"VK_KHR_ray_query"});
    EXPECT_EQ(vk::describeMissing(report, {Capability::RayQuery}),
              report.name +
                  ": missing VK_KHR_ray_query (lavapipe older than Mesa 25.0 has none: install "
                  "mesa-vulkan-drivers from bookworm-backports)");
    return;
  }
  if (gpuTestsOptedOut()) GTEST_SKIP() << "no llvmpipe device";
  FAIL() << "no llvmpipe device";
}

vk::DeviceReport fakeReport(std::string name, uint32_t vendorId, VkDriverId driver,
                            std::vector<std::string> rayQueryMissing) {
  vk::DeviceReport report;
  report.name = std::move(name);
  report.vendorId = vendorId;
  report.driverId = driver;
  report.apiVersion = VK_API_VERSION_1_3;
  for (size_t i = 0; i < vk::kAllCapabilities.size(); ++i) {
    report.capabilities[i].capability = vk::kAllCapabilities[i];
  }
  report.capabilities[size_t(Capability::RayQuery)].missing = std::move(rayQueryMissing);
  return report;
}

TEST(DeviceReport, NvidiaDatacenterGpuWithoutRayQueryPointsToTheOtherBackends) {
  const vk::DeviceReport h100 = fakeReport("NVIDIA H100 80GB HBM3", 0x10DE,
                                           VK_DRIVER_ID_NVIDIA_PROPRIETARY, {"VK_KHR_ray_query"});
  EXPECT_TRUE(h100.supports({Capability::RayTracingPipeline}));
  EXPECT_EQ(vk::describeMissing(h100, {Capability::RayQuery}),
            "NVIDIA H100 80GB HBM3: missing VK_KHR_ray_query (datacenter GPUs expose no ray "
            "query; use --backend pipeline or compute)");
  EXPECT_EQ(vk::describeMissing(h100, {Capability::RayTracingPipeline}), "");
}

TEST(DeviceReport, MissingItemsAreListedOnceWithoutAdviceWhenNoneIsKnown) {
  vk::DeviceReport report = fakeReport("Some GPU", 0x1234, static_cast<VkDriverId>(0),
                                       {"VK_KHR_acceleration_structure", "VK_KHR_ray_query"});
  report.capabilities[size_t(Capability::AccelerationStructure)].missing = {
      "VK_KHR_acceleration_structure"};
  EXPECT_EQ(vk::describeMissing(report, {Capability::RayQuery}),
            "Some GPU: missing VK_KHR_acceleration_structure, VK_KHR_ray_query");
}

TEST(DeviceSupport, OldDeviceMissesVulkan12AndAComputeQueue) {
  vk::DeviceSupport support;
  support.apiVersion = VK_API_VERSION_1_1;
  EXPECT_EQ(vk::missingFor(support, Capability::Compute),
            (std::vector<std::string>{"Vulkan 1.2 (device offers 1.1.0)", "a compute queue"}));
  support.apiVersion = VK_API_VERSION_1_2;
  support.computeQueueFamily = 0;
  EXPECT_EQ(vk::missingFor(support, Capability::Compute),
            std::vector<std::string>{"feature scalarBlockLayout"});
  support.extensions = {"VK_KHR_acceleration_structure", "VK_KHR_deferred_host_operations"};
  support.scalarBlockLayout = true;
  EXPECT_EQ(
      vk::missingFor(support, Capability::AccelerationStructure),
      (std::vector<std::string>{"feature accelerationStructure", "feature bufferDeviceAddress",
                                "VK_KHR_ray_query or VK_KHR_ray_tracing_pipeline"}));
  support.accelerationStructure = support.bufferDeviceAddress = true;
  support.extensions.push_back("VK_KHR_ray_tracing_pipeline");
  support.rayTracingPipeline = true;
  EXPECT_TRUE(vk::missingFor(support, Capability::AccelerationStructure).empty());
}

TEST(CapabilitySet, RayTracingImpliesAccelerationStructuresAndCompute) {
  EXPECT_EQ(CapabilitySet{Capability::RayQuery}.withImplied(),
            (CapabilitySet{Capability::Compute, Capability::AccelerationStructure,
                           Capability::RayQuery}));
  EXPECT_EQ(CapabilitySet{}.withImplied(), CapabilitySet{Capability::Compute});
  EXPECT_EQ(CapabilitySet{Capability::RayTracingPipeline}.withImplied().toString(),
            "compute, acceleration structure, ray tracing pipeline");
}

}  // namespace
}  // namespace amrstream::testing
