#include "vk/descriptor_writes.hpp"

#include <gtest/gtest.h>

#include <array>
#include <stdexcept>
#include <string>

#include "gpu_test.hpp"
#include "vk/descriptor_pool.hpp"
#include "vk/pipelines.hpp"

namespace amrstream::testing {
namespace {

using DescriptorWritesTest = GpuTest;

// Runs `call`, expecting std::logic_error with `part` in its message.
template <typename Call>
void expectLogicError(Call call, const std::string& part) {
  try {
    call();
    ADD_FAILURE() << "no std::logic_error";
  } catch (const std::logic_error& e) {
    EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
  }
}

struct ThreeBufferSet {
  explicit ThreeBufferSet(const vk::Context& ctx)
      : layout(vk::createDescriptorSetLayout(
            ctx, vk::storageBufferBindings(3, VK_SHADER_STAGE_COMPUTE_BIT))),
        pool(ctx, 1, std::array{VkDescriptorPoolSize{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 3}}),
        set(pool.allocate(layout.get())) {}

  vk::UniqueHandle<VkDescriptorSetLayout> layout;
  vk::DescriptorPool pool;
  VkDescriptorSet set;
};

vk::Buffer storageBuffer(const vk::Context& ctx) {
  return vk::Buffer::deviceLocal(ctx, 16, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "target");
}

TEST_F(DescriptorWritesTest, WritesEveryBindingInAnyOrder) {
  const ThreeBufferSet three(ctx());
  const vk::Buffer a = storageBuffer(ctx()), b = storageBuffer(ctx()), c = storageBuffer(ctx());
  vk::DescriptorWrites("test", 3).set(2, c).set(0, a).set(1, b).write(ctx(), three.set);
}

TEST_F(DescriptorWritesTest, RefusesASetWithABindingLeftOut) {
  const ThreeBufferSet three(ctx());
  const vk::Buffer a = storageBuffer(ctx());
  expectLogicError(
      [&] { vk::DescriptorWrites("test", 3).set(0, a).set(2, a).write(ctx(), three.set); },
      "binding 1 of the test set has no target");
}

TEST_F(DescriptorWritesTest, RefusesABindingGivenTwiceOrPastTheCount) {
  const vk::Buffer a = storageBuffer(ctx());
  expectLogicError([&] { vk::DescriptorWrites("test", 3).set(1, a).set(1, a); },
                   "binding 1 of the test set is given a target twice");
  expectLogicError([&] { vk::DescriptorWrites("test", 3).set(3, a); }, "has no binding 3");
}

}  // namespace
}  // namespace amrstream::testing
