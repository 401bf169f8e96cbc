#pragma once
// Submission: a primary command buffer and its fence, recorded and submitted to the context's
// queue without waiting: the host goes on while the device works, and wait() blocks until it is
// done. Submissions on the queue run in submission order only where barriers say so; a barrier's
// first scope includes every earlier submission.
//
//   vk::Submission copy(ctx);
//   copy.submit([&](VkCommandBuffer cmd) { ... });
//   ... host work ...
//   copy.wait();
//   copy.submit(...);  // the next batch of work reuses the command buffer and fence
//
// A repeated submit() waits for the previous one first. The destructor waits for a pending
// submission (the command buffer must outlive the device's use of it). The context must outlive
// the submission.

#include <vulkan/vulkan.h>

#include <utility>

#include "vk/unique_handle.hpp"

namespace amrstream::vk {

class Context;

class Submission {
 public:
  explicit Submission(const Context& ctx);
  Submission(Submission&& other) noexcept;
  Submission& operator=(Submission&& other) noexcept;
  ~Submission();

  template <typename Record>
  void submit(Record&& record) {
    begin();
    std::forward<Record>(record)(commandBuffer_.get());
    submitRecorded();
  }

  // Blocks until the device has finished the commands; throws VulkanError on a lost device.
  void wait();
  bool pending() const { return pending_; }

 private:
  void begin();
  void submitRecorded();
  void waitQuietly() noexcept;

  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  UniqueHandle<VkCommandBuffer> commandBuffer_;
  UniqueHandle<VkFence> fence_;
  bool pending_ = false;
};

}  // namespace amrstream::vk
