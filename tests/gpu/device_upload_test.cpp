#include "gpu/device_upload.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <numeric>
#include <vector>

#include "gpu/staging_ring.hpp"
#include "gpu_test.hpp"
#include "vk/buffer_transfer.hpp"

namespace amrstream::gpu {
namespace {

constexpr VkBufferUsageFlags kReadable =
    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT;

using UploadTest = testing::GpuTest;

// Chunks far smaller than the arrays, and not a multiple of a 12-byte element: every chunk is
// filled with whole elements at the right offset, whether copied or generated.
TEST_F(UploadTest, ChunkedUploadsEqualTheirContents) {
  DeviceUploader uploader(ctx(), 40);
  std::vector<std::uint32_t> words(1001);
  std::iota(words.begin(), words.end(), 7u);
  const vk::Buffer copied = uploader.upload(std::span<const std::uint32_t>(words), kReadable, "w");
  EXPECT_EQ(vk::readBackAs<std::uint32_t>(ctx(), copied), words);

  using Triple = std::array<std::uint32_t, 3>;
  std::vector<std::size_t> firsts;
  const vk::Buffer generated = uploader.upload<Triple>(
      257, kReadable, "triples", [&](std::size_t first, std::span<Triple> out) {
        firsts.push_back(first);
        EXPECT_LE(out.size(), 3u);  // 40 bytes hold 3 whole triples
        for (std::size_t i = 0; i < out.size(); ++i) {
          const auto k = static_cast<std::uint32_t>(first + i);
          out[i] = {k, 2 * k, 3 * k};
        }
      });
  const std::vector<Triple> back = vk::readBackAs<Triple>(ctx(), generated);
  ASSERT_EQ(back.size(), 257u);
  for (std::uint32_t k = 0; k < 257; ++k) EXPECT_EQ(back[k], (Triple{k, 2 * k, 3 * k}));
  EXPECT_EQ(firsts.size(), 86u);  // ceil(257 / 3)

  const vk::Buffer empty = uploader.upload(std::span<const std::uint32_t>(), kReadable, "none");
  EXPECT_EQ(empty.size(), 0u);
}

TEST_F(UploadTest, StagingRingRefusesEmptySlotsAndHandsOutMappedBuffers) {
  EXPECT_THROW(StagingRing(ctx(), 0, 1024), std::invalid_argument);
  EXPECT_THROW(StagingRing(ctx(), 2, 0), std::invalid_argument);
  StagingRing ring(ctx(), 3, 4096);
  EXPECT_EQ(ring.hostBytes(), 3u * 4096u);
  for (std::size_t slot = 0; slot < ring.slots(); ++slot) {
    EXPECT_EQ(ring.buffer(slot).size(), 4096u);
    EXPECT_TRUE(ring.buffer(slot).isMapped());
  }
}

}  // namespace
}  // namespace amrstream::gpu
