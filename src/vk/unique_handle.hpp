#pragma once
// UniqueHandle<H>: sole owner of one Vulkan handle H plus whatever its destroy call needs (the
// parent device or instance, the command pool, an extension's destroy entry point). Move-only;
// the destructor destroys a non-null handle. Owning classes declare their UniqueHandle members
// in creation order, so C++'s reverse-order member destruction tears objects down children
// first with no hand-kept destroy list.
//
// Adding a handle type: specialise HandleTraits with its Owner type and destroy().

#include <vulkan/vulkan.h>

#include <utility>

namespace amrstream::vk {

// Non-dispatchable handles are distinct pointer types only on 64-bit targets; on 32-bit ones they
// are all uint64_t and the specialisations below would collide.
static_assert(sizeof(void*) == 8, "amrstream::vk needs a 64-bit target");

template <typename Handle>
struct HandleTraits;

// Instances and devices have no parent.
struct NoOwner {};

struct CommandBufferOwner {
  VkDevice device = VK_NULL_HANDLE;
  VkCommandPool pool = VK_NULL_HANDLE;
};

struct AccelerationStructureOwner {
  VkDevice device = VK_NULL_HANDLE;
  PFN_vkDestroyAccelerationStructureKHR destroy = nullptr;
};

struct DebugMessengerOwner {
  VkInstance instance = VK_NULL_HANDLE;
  PFN_vkDestroyDebugUtilsMessengerEXT destroy = nullptr;
};

template <>
struct HandleTraits<VkInstance> {
  using Owner = NoOwner;
  static void destroy(NoOwner, VkInstance h) { vkDestroyInstance(h, nullptr); }
};

template <>
struct HandleTraits<VkDevice> {
  using Owner = NoOwner;
  static void destroy(NoOwner, VkDevice h) { vkDestroyDevice(h, nullptr); }
};

template <>
struct HandleTraits<VkCommandBuffer> {
  using Owner = CommandBufferOwner;
  static void destroy(CommandBufferOwner o, VkCommandBuffer h) {
    vkFreeCommandBuffers(o.device, o.pool, 1, &h);
  }
};

template <>
struct HandleTraits<VkAccelerationStructureKHR> {
  using Owner = AccelerationStructureOwner;
  static void destroy(AccelerationStructureOwner o, VkAccelerationStructureKHR h) {
    o.destroy(o.device, h, nullptr);
  }
};

template <>
struct HandleTraits<VkDebugUtilsMessengerEXT> {
  using Owner = DebugMessengerOwner;
  static void destroy(DebugMessengerOwner o, VkDebugUtilsMessengerEXT h) {
    o.destroy(o.instance, h, nullptr);
  }
};

// A surface is a child of the instance, not of a device.
template <>
struct HandleTraits<VkSurfaceKHR> {
  using Owner = VkInstance;
  static void destroy(VkInstance instance, VkSurfaceKHR h) {
    vkDestroySurfaceKHR(instance, h, nullptr);
  }
};

#define AMRSTREAM_DEVICE_CHILD(Type, destroyFunction)                                     \
  template <>                                                                             \
  struct HandleTraits<Type> {                                                             \
    using Owner = VkDevice;                                                               \
    static void destroy(VkDevice device, Type h) { destroyFunction(device, h, nullptr); } \
  };
AMRSTREAM_DEVICE_CHILD(VkBuffer, vkDestroyBuffer)
AMRSTREAM_DEVICE_CHILD(VkDeviceMemory, vkFreeMemory)
AMRSTREAM_DEVICE_CHILD(VkImage, vkDestroyImage)
AMRSTREAM_DEVICE_CHILD(VkImageView, vkDestroyImageView)
AMRSTREAM_DEVICE_CHILD(VkSampler, vkDestroySampler)
AMRSTREAM_DEVICE_CHILD(VkCommandPool, vkDestroyCommandPool)
AMRSTREAM_DEVICE_CHILD(VkFence, vkDestroyFence)
AMRSTREAM_DEVICE_CHILD(VkSemaphore, vkDestroySemaphore)
AMRSTREAM_DEVICE_CHILD(VkQueryPool, vkDestroyQueryPool)
AMRSTREAM_DEVICE_CHILD(VkShaderModule, vkDestroyShaderModule)
AMRSTREAM_DEVICE_CHILD(VkPipeline, vkDestroyPipeline)
AMRSTREAM_DEVICE_CHILD(VkPipelineLayout, vkDestroyPipelineLayout)
AMRSTREAM_DEVICE_CHILD(VkPipelineCache, vkDestroyPipelineCache)
AMRSTREAM_DEVICE_CHILD(VkDescriptorSetLayout, vkDestroyDescriptorSetLayout)
AMRSTREAM_DEVICE_CHILD(VkDescriptorPool, vkDestroyDescriptorPool)
AMRSTREAM_DEVICE_CHILD(VkRenderPass, vkDestroyRenderPass)
AMRSTREAM_DEVICE_CHILD(VkFramebuffer, vkDestroyFramebuffer)
AMRSTREAM_DEVICE_CHILD(VkSwapchainKHR, vkDestroySwapchainKHR)
#undef AMRSTREAM_DEVICE_CHILD

template <typename Handle>
class UniqueHandle {
 public:
  using Owner = typename HandleTraits<Handle>::Owner;

  UniqueHandle() = default;
  UniqueHandle(Owner owner, Handle handle) noexcept : owner_(owner), handle_(handle) {}
  ~UniqueHandle() { reset(); }

  UniqueHandle(const UniqueHandle&) = delete;
  UniqueHandle& operator=(const UniqueHandle&) = delete;
  UniqueHandle(UniqueHandle&& other) noexcept
      : owner_(other.owner_), handle_(std::exchange(other.handle_, VK_NULL_HANDLE)) {}
  UniqueHandle& operator=(UniqueHandle&& other) noexcept {
    if (this != &other) {
      reset();
      owner_ = other.owner_;
      handle_ = std::exchange(other.handle_, VK_NULL_HANDLE);
    }
    return *this;
  }

  Handle get() const { return handle_; }
  const Owner& owner() const { return owner_; }
  explicit operator bool() const { return handle_ != VK_NULL_HANDLE; }

  void reset() noexcept {
    if (handle_ != VK_NULL_HANDLE) {
      HandleTraits<Handle>::destroy(owner_, std::exchange(handle_, VK_NULL_HANDLE));
    }
  }

 private:
  Owner owner_{};
  Handle handle_ = VK_NULL_HANDLE;
};

}  // namespace amrstream::vk
