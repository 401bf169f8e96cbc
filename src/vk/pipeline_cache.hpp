#pragma once
// PipelineCache: the device's VkPipelineCache, kept in a file between runs so that the second run
// of a command compiles no kernel. Every pipeline the project creates goes through it.
//
// The file lies in the cache directory (cacheDirectoryFromEnvironment) under a name that holds
// the vendor, the device, the driver's version and the driver's pipeline cache UUID, so devices
// and drivers never share one. A file that is not whole (its length or checksum disagrees), is
// larger than kMaxPipelineCacheFileBytes, or whose Vulkan header names another device or driver,
// is ignored and replaced. The cache is written when it is destroyed, only if its data changed,
// through a temporary file renamed over the old one, so processes that run at once (MPI ranks)
// never read a half-written file. A file that cannot be read or written only means compiling
// again: it is never an error.

#include <vulkan/vulkan.h>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "vk/unique_handle.hpp"

namespace amrstream::vk {

// Larger files are ignored (and replaced by this run's pipelines alone), which bounds the file as
// new builds add kernels.
inline constexpr std::uint64_t kMaxPipelineCacheFileBytes = 64ull << 20;

// $AMRSTREAM_CACHE_DIR, else $XDG_CACHE_HOME/amrstream, else $HOME/.cache/amrstream; none when
// AMRSTREAM_CACHE_DIR is set but empty, or when neither it, XDG_CACHE_HOME nor HOME is set.
std::optional<std::filesystem::path> cacheDirectoryFromEnvironment();

// pipelines-VVVV-DDDD-VERSION-UUID.bin, in hexadecimal.
std::string pipelineCacheFileName(const VkPhysicalDeviceProperties& properties);

class PipelineCache {
 public:
  // Loads `directory`/pipelineCacheFileName(properties) when it exists and fits; with no
  // directory, the cache lives in memory only.
  PipelineCache(VkDevice device, const VkPhysicalDeviceProperties& properties,
                std::optional<std::filesystem::path> directory);
  PipelineCache(const PipelineCache&) = delete;
  PipelineCache& operator=(const PipelineCache&) = delete;
  ~PipelineCache();

  VkPipelineCache handle() const { return cache_.get(); }
  // The path of the file, when the cache has one.
  const std::optional<std::filesystem::path>& file() const { return file_; }
  // The bytes of pipeline data taken from the file: 0 when it was absent, foreign or damaged.
  std::size_t loadedBytes() const { return loadedBytes_; }
  // Writes the data now if it changed since it was loaded or last saved; false when it could
  // not (no directory, or the write failed).
  bool save();

 private:
  VkDevice device_;
  VkPhysicalDeviceProperties properties_;
  std::optional<std::filesystem::path> file_;
  UniqueHandle<VkPipelineCache> cache_;
  std::size_t loadedBytes_ = 0;
  std::uint32_t savedChecksum_ = 0;
  std::size_t savedBytes_ = 0;
};

}  // namespace amrstream::vk
