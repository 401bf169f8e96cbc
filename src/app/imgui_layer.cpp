#include "app/imgui_layer.hpp"

#include <imgui.h>
#include <vulkan/vulkan.h>
// After vulkan.h, so that GLFW declares its Vulkan functions.
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_vulkan.h>

#include <algorithm>
#include <stdexcept>

#include "app/window.hpp"
#include "vk/commands.hpp"
#include "vk/context.hpp"
#include "vk/debug_names.hpp"
#include "vk/vk_error.hpp"

namespace amrstream::app {
namespace {

bool layerExists = false;

void (*claim())() {
  if (layerExists) throw std::logic_error("only one ImGuiLayer may exist at a time");
  layerExists = true;
  return [] { layerExists = false; };
}

// The backend calls this with every result, VK_SUCCESS included.
void checkBackendResult(VkResult result) {
  if (result < 0) throw vk::VulkanError(result, "Dear ImGui's Vulkan backend failed");
}

vk::UniqueHandle<VkDescriptorPool> createDescriptorPool(const vk::Context& ctx) {
  // The backend allocates one combined image sampler set, for the font atlas.
  const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1};
  VkDescriptorPoolCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  info.maxSets = 1;
  info.poolSizeCount = 1;
  info.pPoolSizes = &size;
  VkDescriptorPool pool = VK_NULL_HANDLE;
  AMRSTREAM_VK_CHECK(vkCreateDescriptorPool(ctx.device(), &info, nullptr, &pool));
  vk::UniqueHandle<VkDescriptorPool> owned(ctx.device(), pool);
  vk::setDebugName(ctx, owned, "imgui descriptors");
  return owned;
}

void (*startContext())() {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // no imgui.ini in whatever directory the viewer was started from
  ImGui::StyleColorsDark();
  return [] { ImGui::DestroyContext(); };
}

void (*startGlfwBackend(Window& window))() {
  if (!ImGui_ImplGlfw_InitForVulkan(window.handle(), true)) {
    throw std::runtime_error("Dear ImGui's GLFW backend failed to start");
  }
  return [] { ImGui_ImplGlfw_Shutdown(); };
}

void (*startVulkanBackend(const vk::Context& ctx, VkDescriptorPool pool, VkRenderPass renderPass,
                          uint32_t framesInFlight))() {
  ImGui_ImplVulkan_InitInfo info{};
  info.Instance = ctx.instance();
  info.PhysicalDevice = ctx.physicalDevice();
  info.Device = ctx.device();
  info.QueueFamily = ctx.queueFamilyIndex();
  info.Queue = ctx.queue();
  info.DescriptorPool = pool;
  info.Subpass = 0;
  // The backend only checks MinImageCount; ImageCount is the number of vertex buffer sets it
  // cycles through, one per frame in flight.
  info.MinImageCount = 2;
  info.ImageCount = std::max(framesInFlight, 2u);
  info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
  info.CheckVkResultFn = &checkBackendResult;
  if (!ImGui_ImplVulkan_Init(&info, renderPass)) {
    throw std::runtime_error("Dear ImGui's Vulkan backend failed to start");
  }
  return [] { ImGui_ImplVulkan_Shutdown(); };
}

}  // namespace

ImGuiLayer::ImGuiLayer(const vk::Context& ctx, Window& window, VkRenderPass renderPass,
                       uint32_t framesInFlight)
    : ctx_(&ctx),
      claim_(claim()),
      descriptorPool_(createDescriptorPool(ctx)),
      imguiContext_(startContext()),
      glfwBackend_(startGlfwBackend(window)),
      vulkanBackend_(startVulkanBackend(ctx, descriptorPool_.get(), renderPass, framesInFlight)) {
  vk::submitAndWait(ctx, [](VkCommandBuffer cmd) {
    if (!ImGui_ImplVulkan_CreateFontsTexture(cmd)) {
      throw std::runtime_error("Dear ImGui's Vulkan backend could not upload its fonts");
    }
  });
  ImGui_ImplVulkan_DestroyFontUploadObjects();
}

ImGuiLayer::~ImGuiLayer() {
  if (frameStarted_) ImGui::EndFrame();
  // The backend's pipeline, buffers and font image may still be used by frames in flight.
  vkDeviceWaitIdle(ctx_->device());
}

void ImGuiLayer::newFrame() {
  if (frameStarted_) ImGui::EndFrame();
  ImGui_ImplVulkan_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  frameStarted_ = true;
}

InputFrame ImGuiLayer::uncaptured(InputFrame input) const {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantCaptureMouse) {
    input.cursorDelta = glm::dvec2(0.0);
    input.scroll = glm::dvec2(0.0);
    input.buttonsDown = {};
  }
  if (io.WantCaptureKeyboard) input.keyPresses.clear();
  return input;
}

void ImGuiLayer::record(VkCommandBuffer cmd) {
  if (!frameStarted_) return;
  frameStarted_ = false;
  ImGui::Render();
  ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), cmd);
}

}  // namespace amrstream::app
