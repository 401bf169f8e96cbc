#include "vk/submission.hpp"

#include "vk/context.hpp"
#include "vk/vk_error.hpp"

namespace amrstream::vk {

Submission::Submission(const Context& ctx) : device_(ctx.device()), queue_(ctx.queue()) {
  VkCommandBufferAllocateInfo info{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  info.commandPool = ctx.commandPool();
  info.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  info.commandBufferCount = 1;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  AMRSTREAM_VK_CHECK(vkAllocateCommandBuffers(device_, &info, &cmd));
  commandBuffer_ = UniqueHandle<VkCommandBuffer>({device_, ctx.commandPool()}, cmd);

  VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  VkFence fence = VK_NULL_HANDLE;
  AMRSTREAM_VK_CHECK(vkCreateFence(device_, &fenceInfo, nullptr, &fence));
  fence_ = UniqueHandle<VkFence>(device_, fence);
}

void Submission::begin() {
  wait();
  const VkFence fence = fence_.get();
  AMRSTREAM_VK_CHECK(vkResetFences(device_, 1, &fence));
  // The pool lets each buffer be reset on its own; beginning a one-time buffer resets it.
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  AMRSTREAM_VK_CHECK(vkBeginCommandBuffer(commandBuffer_.get(), &begin));
}

void Submission::submitRecorded() {
  const VkCommandBuffer cmd = commandBuffer_.get();
  AMRSTREAM_VK_CHECK(vkEndCommandBuffer(cmd));
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &cmd;
  AMRSTREAM_VK_CHECK(vkQueueSubmit(queue_, 1, &submit, fence_.get()));
  pending_ = true;
}

Submission::Submission(Submission&& other) noexcept
    : device_(other.device_),
      queue_(other.queue_),
      commandBuffer_(std::move(other.commandBuffer_)),
      fence_(std::move(other.fence_)),
      pending_(std::exchange(other.pending_, false)) {}

Submission& Submission::operator=(Submission&& other) noexcept {
  if (this != &other) {
    waitQuietly();
    device_ = other.device_;
    queue_ = other.queue_;
    commandBuffer_ = std::move(other.commandBuffer_);
    fence_ = std::move(other.fence_);
    pending_ = std::exchange(other.pending_, false);
  }
  return *this;
}

Submission::~Submission() { waitQuietly(); }

void Submission::wait() {
  if (!pending_) return;
  const VkFence fence = fence_.get();
  // No timeout: a long round on a CPU device can take minutes, and a lost device returns
  // VK_ERROR_DEVICE_LOST rather than hanging.
  const VkResult result = vkWaitForFences(device_, 1, &fence, VK_TRUE, UINT64_MAX);
  if (result != VK_SUCCESS) vkQueueWaitIdle(queue_);
  pending_ = false;
  AMRSTREAM_VK_CHECK(result);
}

void Submission::waitQuietly() noexcept {
  if (!pending_) return;
  const VkFence fence = fence_.get();
  if (vkWaitForFences(device_, 1, &fence, VK_TRUE, UINT64_MAX) != VK_SUCCESS)
    vkQueueWaitIdle(queue_);
  pending_ = false;
}

}  // namespace amrstream::vk
