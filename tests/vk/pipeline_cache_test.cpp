#include "vk/pipeline_cache.hpp"

#include <gtest/gtest.h>
#include <zlib.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include "../../shaders/glsl/shared/round_bindings.h"
#include "../../shaders/glsl/shared/round_params.h"
#include "gpu_test.hpp"
#include "scan_lines_comp.h"
#include "vk/context.hpp"
#include "vk/pipelines.hpp"

namespace amrstream::testing {
namespace {

namespace fs = std::filesystem;

std::vector<char> fileBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

void writeBytes(const fs::path& path, const std::vector<char>& bytes) {
  std::ofstream(path, std::ios::binary | std::ios::trunc)
      .write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

class PipelineCacheTest : public ::testing::Test {
 protected:
  void SetUp() override {
    directory_ = fs::temp_directory_path() /
                 ("amrstream-pipeline-cache-" +
                  std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(directory_);
    try {
      (void)validatedBuilder({vk::Capability::Compute})
          .pipelineCacheDirectory(std::nullopt)
          .build();
    } catch (const vk::ContextError& error) {
      if (gpuTestsOptedOut()) GTEST_SKIP() << error.what();
    }
  }
  void TearDown() override { fs::remove_all(directory_); }

  // A context on the cache directory that creates one compute pipeline and is destroyed,
  // returning the bytes it loaded from the file. Fails on validation errors.
  std::size_t runOnce() {
    std::size_t loaded = 0;
    try {
      vk::Context ctx =
          validatedBuilder({vk::Capability::Compute}).pipelineCacheDirectory(directory_).build();
      loaded = ctx.pipelineCacheFile().loadedBytes();
      file_ = *ctx.pipelineCacheFile().file();
      const auto setLayout = vk::createDescriptorSetLayout(
          ctx, vk::storageBufferBindings(AMRSTREAM_COMPACTION_BINDING_COUNT,
                                         VK_SHADER_STAGE_COMPUTE_BIT));
      const auto layout = vk::createPipelineLayout(
          ctx, setLayout.get(), sizeof(shared::CompactionParams), VK_SHADER_STAGE_COMPUTE_BIT);
      const auto pipeline = vk::createComputePipeline(
          ctx, layout.get(), vk::spirv(amrstream_spirv_scan_lines_comp), nullptr, "scan lines");
      EXPECT_NE(pipeline.get(), VK_NULL_HANDLE);
      log_ = ctx.validationLog();
    } catch (const vk::ContextError& error) {
      ADD_FAILURE() << error.what();
    }
    if (log_) expectNoValidationErrors(*log_);
    return loaded;
  }

  fs::path directory_;
  fs::path file_;
  std::shared_ptr<const vk::ValidationLog> log_;
};

TEST_F(PipelineCacheTest, SecondContextLoadsWhatTheFirstSaved) {
  EXPECT_EQ(runOnce(), 0u);
  if (IsSkipped()) return;
  ASSERT_TRUE(fs::exists(file_)) << file_;
  EXPECT_EQ(file_.parent_path(), directory_);
  EXPECT_EQ(runOnce(), fs::file_size(file_) - 24);  // the file's own header is 24 bytes
}

TEST_F(PipelineCacheTest, DamagedFilesAreIgnoredAndReplaced) {
  runOnce();
  if (IsSkipped()) return;
  const std::vector<char> whole = fileBytes(file_);
  ASSERT_GE(whole.size(),
            24u + 32u);  // ours, then at least the Vulkan header (lavapipe keeps no more)

  std::vector<char> truncated(whole.begin(), whole.end() - 1);
  writeBytes(file_, truncated);
  EXPECT_EQ(runOnce(), 0u) << "a truncated file";
  EXPECT_EQ(fileBytes(file_).size(), whole.size()) << "rewritten whole";

  std::vector<char> flipped = whole;
  flipped.back() ^= 0x5a;
  writeBytes(file_, flipped);
  EXPECT_EQ(runOnce(), 0u) << "a file whose checksum disagrees";

  writeBytes(file_, std::vector<char>(4096, 'x'));
  EXPECT_EQ(runOnce(), 0u) << "a file of another kind";
  EXPECT_EQ(runOnce(), whole.size() - 24) << "the rewritten file loads again";
}

TEST_F(PipelineCacheTest, AnotherDevicesDataIsIgnored) {
  runOnce();
  if (IsSkipped()) return;
  std::vector<char> foreign = fileBytes(file_);
  // The Vulkan header's vendor ID (after the file's 24 bytes, headerSize and headerVersion), with
  // the file's checksum (bytes 16 to 19) made to agree: only the header check can refuse it.
  foreign[24 + 8] ^= 0x01;
  const auto sum = static_cast<std::uint32_t>(
      crc32(0, reinterpret_cast<const Bytef*>(foreign.data() + 24), foreign.size() - 24));
  std::memcpy(foreign.data() + 16, &sum, sizeof sum);
  writeBytes(file_, foreign);
  EXPECT_EQ(runOnce(), 0u);
  EXPECT_NE(fileBytes(file_), foreign) << "replaced by this device's data";
}

TEST(PipelineCacheDirectory, FollowsTheEnvironment) {
  const auto keep = [](const char* name) {
    const char* value = std::getenv(name);
    return value ? std::optional<std::string>(value) : std::nullopt;
  };
  const auto own = keep("AMRSTREAM_CACHE_DIR"), xdg = keep("XDG_CACHE_HOME"), home = keep("HOME");
  ::setenv("HOME", "/home/u", 1);
  ::unsetenv("XDG_CACHE_HOME");
  ::unsetenv("AMRSTREAM_CACHE_DIR");
  EXPECT_EQ(vk::cacheDirectoryFromEnvironment(), fs::path("/home/u/.cache/amrstream"));
  ::setenv("XDG_CACHE_HOME", "/x", 1);
  EXPECT_EQ(vk::cacheDirectoryFromEnvironment(), fs::path("/x/amrstream"));
  ::setenv("AMRSTREAM_CACHE_DIR", "/c", 1);
  EXPECT_EQ(vk::cacheDirectoryFromEnvironment(), fs::path("/c"));
  ::setenv("AMRSTREAM_CACHE_DIR", "", 1);
  EXPECT_EQ(vk::cacheDirectoryFromEnvironment(), std::nullopt);
  const auto restore = [](const char* name, const std::optional<std::string>& value) {
    if (value)
      ::setenv(name, value->c_str(), 1);
    else
      ::unsetenv(name);
  };
  restore("AMRSTREAM_CACHE_DIR", own);
  restore("XDG_CACHE_HOME", xdg);
  restore("HOME", home);
}

TEST(PipelineCacheFileName, NamesVendorDeviceDriverAndUuid) {
  VkPhysicalDeviceProperties properties{};
  properties.vendorID = 0x10de;
  properties.deviceID = 0x2330;
  properties.driverVersion = 0x91180000;
  for (int i = 0; i < VK_UUID_SIZE; ++i) properties.pipelineCacheUUID[i] = std::uint8_t(i);
  EXPECT_EQ(vk::pipelineCacheFileName(properties),
            "pipelines-10de-2330-91180000-000102030405060708090a0b0c0d0e0f.bin");
}

}  // namespace
}  // namespace amrstream::testing
