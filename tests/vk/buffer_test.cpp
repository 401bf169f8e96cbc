#include "vk/buffer.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "gpu_test.hpp"
#include "vk/buffer_transfer.hpp"
#include "vk/commands.hpp"
#include "vk/vk_error.hpp"

namespace amrstream::testing {
namespace {

std::vector<std::byte> randomBytes(size_t count, uint32_t seed) {
  std::mt19937 random(seed);
  std::vector<std::byte> bytes(count);
  for (auto& b : bytes) b = static_cast<std::byte>(random() & 0xFF);
  return bytes;
}

using BufferTest = GpuTest;

TEST_F(BufferTest, RoundTripThroughStagingAndACopyCommand) {
  const std::vector<std::byte> bytes = randomBytes((1 << 20) + 3, 42);
  const vk::Buffer device = vk::uploadToDeviceLocal(ctx(), std::span<const std::byte>(bytes),
                                                    VK_BUFFER_USAGE_TRANSFER_SRC_BIT, "round trip");
  EXPECT_EQ(device.size(), bytes.size());
  EXPECT_FALSE(device.isMapped());

  const vk::Buffer readback =
      vk::Buffer::readback(ctx(), bytes.size(), VK_BUFFER_USAGE_TRANSFER_DST_BIT, "readback");
  vk::submitAndWait(ctx(), [&](VkCommandBuffer cmd) {
    const VkBufferCopy region{0, 0, bytes.size()};
    vkCmdCopyBuffer(cmd, device.handle(), readback.handle(), 1, &region);
    vk::memoryBarrier(cmd, vk::access::kTransferWrite, vk::access::kHostRead);
  });
  readback.invalidateMapped();
  ASSERT_EQ(readback.mapped().size(), bytes.size());
  EXPECT_EQ(std::memcmp(readback.mapped().data(), bytes.data(), bytes.size()), 0);

  EXPECT_EQ(vk::readBack(ctx(), device), bytes);
}

TEST_F(BufferTest, TypedUploadAndReadBack) {
  const std::vector<float> values = {1.5f, -2.0f, 3.25f, 1e30f};
  const vk::Buffer buffer = vk::uploadToDeviceLocal(
      ctx(), values, VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
      "floats");
  EXPECT_EQ(buffer.size(), values.size() * sizeof(float));
  EXPECT_EQ(vk::readBackAs<float>(ctx(), buffer), values);
  EXPECT_THROW(vk::readBackAs<double>(
                   ctx(), vk::uploadToDeviceLocal(ctx(), std::vector<float>{1, 2, 3},
                                                  VK_BUFFER_USAGE_TRANSFER_SRC_BIT, "three")),
               std::invalid_argument);
}

TEST_F(BufferTest, UploadBufferIsMappedAndCoherent) {
  vk::Buffer upload = vk::Buffer::upload(ctx(), 64, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, "upload");
  ASSERT_TRUE(upload.isMapped());
  ASSERT_EQ(upload.mapped().size(), 64u);
  std::memset(upload.mapped().data(), 0xAB, 64);
  const vk::Buffer device = vk::Buffer::deviceLocal(
      ctx(), 64, VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT, "device");
  vk::submitAndWait(ctx(), [&](VkCommandBuffer cmd) {
    const VkBufferCopy region{0, 0, 64};
    vkCmdCopyBuffer(cmd, upload.handle(), device.handle(), 1, &region);
  });
  EXPECT_EQ(vk::readBack(ctx(), device), std::vector<std::byte>(64, std::byte{0xAB}));
}

TEST_F(BufferTest, DeviceAddressOnlyWhenRequested) {
  const VkBufferUsageFlags addressable =
      VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT;
  const vk::Buffer a = vk::Buffer::deviceLocal(ctx(), 256, addressable, "a");
  const vk::Buffer b = vk::Buffer::deviceLocal(ctx(), 256, addressable, "b");
  const vk::Buffer plain =
      vk::Buffer::deviceLocal(ctx(), 256, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "plain");
  EXPECT_NE(a.deviceAddress(), 0u);
  EXPECT_NE(b.deviceAddress(), 0u);
  EXPECT_NE(a.deviceAddress(), b.deviceAddress());
  EXPECT_EQ(plain.deviceAddress(), 0u);
}

TEST_F(BufferTest, ZeroSizeBuffersAreValidAndEmpty) {
  const vk::Buffer device = vk::Buffer::deviceLocal(
      ctx(), 0, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
      "empty");
  EXPECT_NE(device.handle(), VK_NULL_HANDLE);
  EXPECT_EQ(device.size(), 0u);
  EXPECT_NE(device.deviceAddress(), 0u);
  const vk::Buffer upload = vk::Buffer::upload(ctx(), 0, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, "e");
  EXPECT_TRUE(upload.isMapped());
  EXPECT_TRUE(upload.mapped().empty());
  const vk::Buffer uploaded = vk::uploadToDeviceLocal(
      ctx(), std::span<const std::byte>(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT, "uploaded empty");
  EXPECT_EQ(uploaded.size(), 0u);
  EXPECT_TRUE(vk::readBack(ctx(), uploaded).empty());
}

TEST_F(BufferTest, AbsurdSizeFailsWithTheNameAndTheSize) {
  constexpr VkDeviceSize kOnePebibyte = VkDeviceSize{1} << 50;
  for (auto make : {&vk::Buffer::deviceLocal, &vk::Buffer::upload, &vk::Buffer::readback}) {
    try {
      make(ctx(), kOnePebibyte, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "positions");
      FAIL() << "expected a VulkanError";
    } catch (const vk::VulkanError& error) {
      const std::string message = error.what();
      EXPECT_NE(message.find("allocating 'positions' (1.0 PiB)"), std::string::npos) << message;
      EXPECT_TRUE(error.result() == VK_ERROR_OUT_OF_DEVICE_MEMORY ||
                  error.result() == VK_ERROR_OUT_OF_HOST_MEMORY)
          << message;
    }
  }
}

TEST_F(BufferTest, ReadBackNeedsTransferSource) {
  const vk::Buffer buffer =
      vk::Buffer::deviceLocal(ctx(), 16, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "no source");
  try {
    vk::readBack(ctx(), buffer);
    FAIL() << "expected a VulkanError";
  } catch (const vk::VulkanError& error) {
    EXPECT_NE(std::string(error.what()).find("'no source'"), std::string::npos) << error.what();
  }
}

TEST_F(BufferTest, MovedFromBufferIsEmpty) {
  vk::Buffer a = vk::Buffer::upload(ctx(), 32, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, "a");
  const VkBuffer handle = a.handle();
  vk::Buffer b = std::move(a);
  EXPECT_EQ(b.handle(), handle);
  EXPECT_EQ(b.mapped().size(), 32u);
  EXPECT_EQ(a.handle(), VK_NULL_HANDLE);
  EXPECT_FALSE(a.isMapped());
  EXPECT_EQ(a.size(), 0u);
  b = vk::Buffer::deviceLocal(ctx(), 8, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "c");
  EXPECT_EQ(b.name(), "c");
  EXPECT_FALSE(b.isMapped());
}

TEST(VulkanError, CheckMacroCarriesResultExpressionAndLocation) {
  try {
    AMRSTREAM_VK_CHECK(VK_ERROR_DEVICE_LOST);
    FAIL() << "expected a VulkanError";
  } catch (const vk::VulkanError& error) {
    EXPECT_EQ(error.result(), VK_ERROR_DEVICE_LOST);
    EXPECT_EQ(error.expression(), "VK_ERROR_DEVICE_LOST");
    EXPECT_NE(error.file().find("buffer_test.cpp"), std::string::npos);
    EXPECT_GT(error.line(), 0);
    EXPECT_NE(std::string(error.what()).find("failed with VK_ERROR_DEVICE_LOST at"),
              std::string::npos);
  }
  EXPECT_EQ(vk::formatBytes(512), "512 B");
  EXPECT_EQ(vk::formatBytes(VkDeviceSize{12} << 30 | VkDeviceSize{300} << 20), "12.3 GiB");
}

}  // namespace
}  // namespace amrstream::testing
