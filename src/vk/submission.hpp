#pragma once
// Submission: commands recorded into a fresh primary command buffer and submitted to the
// context's queue with their own fence, without waiting: the host goes on while the device
// works, and wait() blocks until it is done. Submissions on the queue run in submission order
// only where barriers say so; a barrier's first scope includes every earlier submission.
//
//   vk::Submission copy = vk::Submission::submit(ctx, [&](VkCommandBuffer cmd) { ... });
//   ... host work ...
//   copy.wait();
//
// The destructor waits for a pending submission (the command buffer must outlive the device's
// use of it). The context must outlive the submission.

#include <vulkan/vulkan.h>

#include <utility>

#include "vk/unique_handle.hpp"

namespace amrstream::vk {

class Context;

class Submission {
 public:
  template <typename Record>
  static Submission submit(const Context& ctx, Record&& record) {
    Submission s(ctx);
    std::forward<Record>(record)(s.commandBuffer_.get());
    s.submitRecorded();
    return s;
  }

  Submission(Submission&& other) noexcept;
  Submission& operator=(Submission&& other) noexcept;
  ~Submission();

  // Blocks until the device has finished the commands; throws VulkanError on a lost device.
  void wait();
  bool pending() const { return pending_; }

 private:
  explicit Submission(const Context& ctx);
  void submitRecorded();
  void waitQuietly() noexcept;

  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  UniqueHandle<VkCommandBuffer> commandBuffer_;
  UniqueHandle<VkFence> fence_;
  bool pending_ = false;
};

}  // namespace amrstream::vk
