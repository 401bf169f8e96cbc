#include "vk/pipeline_cache.hpp"

#include <fmt/format.h>
#include <unistd.h>
#include <zlib.h>

#include <array>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <system_error>
#include <vector>

#include "vk/vk_error.hpp"

namespace amrstream::vk {

namespace {

// The file: this header, then the driver's data (vkGetPipelineCacheData) whole.
struct FileHeader {
  std::array<char, 8> magic;
  std::uint64_t dataBytes;
  std::uint32_t dataChecksum;  // zlib's crc32 of the data
  std::uint32_t reserved;
};
constexpr std::array<char, 8> kMagic{'A', 'M', 'R', 'S', 'P', 'C', '1', '\0'};

std::uint32_t checksum(const std::vector<char>& data) {
  return static_cast<std::uint32_t>(
      crc32(0, reinterpret_cast<const Bytef*>(data.data()), static_cast<uInt>(data.size())));
}

// Whether the data's Vulkan header (VkPipelineCacheHeaderVersionOne) names this device and
// driver.
bool writtenForDevice(const std::vector<char>& data, const VkPhysicalDeviceProperties& device) {
  VkPipelineCacheHeaderVersionOne header;
  if (data.size() < sizeof header) return false;
  std::memcpy(&header, data.data(), sizeof header);
  return header.headerSize >= sizeof header && header.headerSize <= data.size() &&
         header.headerVersion == VK_PIPELINE_CACHE_HEADER_VERSION_ONE &&
         header.vendorID == device.vendorID && header.deviceID == device.deviceID &&
         std::memcmp(header.pipelineCacheUUID, device.pipelineCacheUUID, VK_UUID_SIZE) == 0;
}

// The file's data when it is whole, fits and was written for this device; empty otherwise.
std::vector<char> readCacheFile(const std::filesystem::path& file,
                                const VkPhysicalDeviceProperties& device) {
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(file, error);
  if (error || size < sizeof(FileHeader) || size > kMaxPipelineCacheFileBytes) return {};
  std::ifstream in(file, std::ios::binary);
  FileHeader header;
  if (!in.read(reinterpret_cast<char*>(&header), sizeof header) || header.magic != kMagic ||
      header.dataBytes != size - sizeof header)
    return {};
  std::vector<char> data(header.dataBytes);
  if (!in.read(data.data(), static_cast<std::streamsize>(data.size())) ||
      checksum(data) != header.dataChecksum || !writtenForDevice(data, device))
    return {};
  return data;
}

// Writes through a temporary file in the same directory, renamed over `file` when whole.
bool writeCacheFile(const std::filesystem::path& file, const std::vector<char>& data) {
  std::error_code error;
  std::filesystem::create_directories(file.parent_path(), error);
  if (error) return false;
  const std::filesystem::path temporary =
      file.parent_path() / fmt::format("{}.{}.tmp", file.filename().string(), ::getpid());
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    const FileHeader header{kMagic, data.size(), checksum(data), 0};
    out.write(reinterpret_cast<const char*>(&header), sizeof header);
    out.write(data.data(), static_cast<std::streamsize>(data.size()));
    if (!out.flush()) {
      out.close();
      std::filesystem::remove(temporary, error);
      return false;
    }
  }
  std::filesystem::rename(temporary, file, error);
  if (error) std::filesystem::remove(temporary, error);
  return !error;
}

std::optional<std::filesystem::path> environmentPath(const char* name) {
  const char* value = std::getenv(name);
  if (value == nullptr || *value == '\0') return std::nullopt;
  return std::filesystem::path(value);
}

}  // namespace

std::optional<std::filesystem::path> cacheDirectoryFromEnvironment() {
  if (const char* own = std::getenv("AMRSTREAM_CACHE_DIR"))
    return *own == '\0' ? std::nullopt : std::optional(std::filesystem::path(own));
  if (const auto xdg = environmentPath("XDG_CACHE_HOME")) return *xdg / "amrstream";
  if (const auto home = environmentPath("HOME")) return *home / ".cache" / "amrstream";
  return std::nullopt;
}

std::string pipelineCacheFileName(const VkPhysicalDeviceProperties& properties) {
  std::string uuid;
  for (const std::uint8_t byte : properties.pipelineCacheUUID) uuid += fmt::format("{:02x}", byte);
  return fmt::format("pipelines-{:04x}-{:04x}-{:08x}-{}.bin", properties.vendorID,
                     properties.deviceID, properties.driverVersion, uuid);
}

PipelineCache::PipelineCache(VkDevice device, const VkPhysicalDeviceProperties& properties,
                             std::optional<std::filesystem::path> directory)
    : device_(device), properties_(properties) {
  std::vector<char> data;
  if (directory) {
    file_ = *directory / pipelineCacheFileName(properties);
    data = readCacheFile(*file_, properties);
  }
  VkPipelineCacheCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO};
  info.initialDataSize = data.size();
  info.pInitialData = data.empty() ? nullptr : data.data();
  VkPipelineCache cache;
  AMRSTREAM_VK_CHECK(vkCreatePipelineCache(device, &info, nullptr, &cache));
  cache_ = {device, cache};
  loadedBytes_ = savedBytes_ = data.size();
  savedChecksum_ = data.empty() ? 0 : checksum(data);
}

PipelineCache::~PipelineCache() { save(); }

bool PipelineCache::save() {
  if (!file_) return false;
  std::size_t size = 0;
  if (vkGetPipelineCacheData(device_, cache_.get(), &size, nullptr) != VK_SUCCESS || size == 0)
    return false;
  std::vector<char> data(size);
  if (vkGetPipelineCacheData(device_, cache_.get(), &size, data.data()) != VK_SUCCESS) return false;
  data.resize(size);
  const std::uint32_t sum = checksum(data);
  if (size == savedBytes_ && sum == savedChecksum_) return true;
  if (size > kMaxPipelineCacheFileBytes || !writeCacheFile(*file_, data)) return false;
  savedBytes_ = size;
  savedChecksum_ = sum;
  return true;
}

}  // namespace amrstream::vk
