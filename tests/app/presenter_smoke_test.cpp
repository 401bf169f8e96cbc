// The presenter end to end: a stand-in renderer writes a moving gradient into a device buffer in
// each frame's command buffer, an ImGui panel is drawn over it, and the screenshot of the last
// frame must show the gradient's exact bytes everywhere outside the panel (bilinear within a
// tolerance where the frame is scaled, the clear colour in the bars), and the panel over it.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <imgui.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/frame_presenter.hpp"
#include "app/imgui_layer.hpp"
#include "vk/buffer.hpp"
#include "vk/context.hpp"
#include "window_test.hpp"

namespace amrstream::testing {
namespace {

using Rgba = std::array<uint8_t, 4>;

// The ImGui panel, in pixels (window coordinates are pixels under Xvfb), and a margin for its
// border.
constexpr int kPanelX = 8;
constexpr int kPanelY = 8;
constexpr int kPanelWidth = 140;
constexpr int kPanelHeight = 60;
constexpr int kMargin = 2;

bool underPanel(uint32_t x, uint32_t y) {
  return int(x) >= kPanelX - kMargin && int(x) < kPanelX + kPanelWidth + kMargin &&
         int(y) >= kPanelY - kMargin && int(y) < kPanelY + kPanelHeight + kMargin;
}

// Strictly inside the panel, away from its border and title bar text.
bool insidePanel(uint32_t x, uint32_t y) {
  return int(x) >= kPanelX + kMargin && int(x) < kPanelX + kPanelWidth - kMargin &&
         int(y) >= kPanelY + kMargin && int(y) < kPanelY + kPanelHeight - kMargin;
}

// The renderer stand-in: red across (shifting 4 pixels a frame), green down, blue by frame.
Rgba gradient(uint32_t x, uint32_t y, VkExtent2D extent, uint32_t frame) {
  const uint32_t shifted = (x + 4 * frame) % extent.width;
  return {uint8_t(shifted * 255 / (extent.width - 1)), uint8_t(y * 255 / (extent.height - 1)),
          uint8_t((frame * 16) & 0xFF), 255};
}

std::vector<uint8_t> gradientImage(VkExtent2D extent, uint32_t frame) {
  std::vector<uint8_t> pixels;
  pixels.reserve(size_t(extent.width) * extent.height * 4);
  for (uint32_t y = 0; y < extent.height; ++y) {
    for (uint32_t x = 0; x < extent.width; ++x) {
      const Rgba p = gradient(x, y, extent, frame);
      pixels.insert(pixels.end(), p.begin(), p.end());
    }
  }
  return pixels;
}

// What a blit with LINEAR filtering samples at the centre of destination pixel (x, y) when
// `source` is stretched over `target`: bilinear, clamped to the edge.
std::array<double, 4> bilinear(uint32_t x, uint32_t y, VkExtent2D source, VkExtent2D target,
                               uint32_t frame) {
  const double u = (x + 0.5) * source.width / target.width - 0.5;
  const double v = (y + 0.5) * source.height / target.height - 0.5;
  const double fu = u - std::floor(u);
  const double fv = v - std::floor(v);
  auto clampTo = [](double i, uint32_t size) {
    return uint32_t(std::clamp(i, 0.0, double(size - 1)));
  };
  const uint32_t x0 = clampTo(std::floor(u), source.width);
  const uint32_t x1 = clampTo(std::floor(u) + 1, source.width);
  const uint32_t y0 = clampTo(std::floor(v), source.height);
  const uint32_t y1 = clampTo(std::floor(v) + 1, source.height);
  std::array<double, 4> out{};
  for (int c = 0; c < 4; ++c) {
    const double top =
        (1 - fu) * gradient(x0, y0, source, frame)[c] + fu * gradient(x1, y0, source, frame)[c];
    const double bottom =
        (1 - fu) * gradient(x0, y1, source, frame)[c] + fu * gradient(x1, y1, source, frame)[c];
    out[c] = (1 - fv) * top + fv * bottom;
  }
  return out;
}

// Records the upload of `pixels` into `buffer` (vkCmdUpdateBuffer takes 65536 bytes at most).
void recordUpload(VkCommandBuffer cmd, VkBuffer buffer, const std::vector<uint8_t>& pixels) {
  constexpr size_t kChunk = 65536;
  for (size_t offset = 0; offset < pixels.size(); offset += kChunk) {
    vkCmdUpdateBuffer(cmd, buffer, offset, std::min(kChunk, pixels.size() - offset),
                      pixels.data() + offset);
  }
}

std::string describe(Rgba p) { return fmt::format("({}, {}, {}, {})", p[0], p[1], p[2], p[3]); }

// Counts the pixels outside the panel where `expected` returns false, describing the first.
struct Mismatches {
  size_t count = 0;
  size_t compared = 0;
  std::string first;
};

Mismatches compareOutsidePanel(const app::Screenshot& shot,
                               const std::function<bool(uint32_t, uint32_t, Rgba)>& expected) {
  Mismatches m;
  for (uint32_t y = 0; y < shot.height; ++y) {
    for (uint32_t x = 0; x < shot.width; ++x) {
      if (underPanel(x, y)) continue;
      ++m.compared;
      const Rgba p = shot.pixel(x, y);
      if (expected(x, y, p)) continue;
      if (m.count++ == 0) {
        m.first = fmt::format("at ({}, {}): {}", x, y, describe(p));
      }
    }
  }
  return m;
}

class PresenterTest : public WindowTest {
 protected:
  struct Run {
    app::Screenshot shot;
    uint32_t lastFrame = 0;
    double millisecondsPerFrame = 0;
  };

  void SetUp() override {
    WindowTest::SetUp();
    if (IsSkipped() || HasFatalFailure()) return;
    try {
      buildPresentingContext();
    } catch (const vk::ContextError& error) {
      unavailable(error.what());
    }
  }

  void TearDown() override {
    imgui_.reset();
    presenter_.reset();
    WindowTest::TearDown();
  }

  void start(const app::PresenterOptions& options = {}) {
    presenter_.emplace(*ctx_, window(), options);
    imgui_.emplace(*ctx_, window(), presenter_->overlayRenderPass(), presenter_->framesInFlight());
  }

  // Presents `frames` frames of the gradient at `source` (no buffer when it is empty) under the
  // ImGui panel, taking a screenshot of the last.
  Run present(VkExtent2D source, uint32_t frames) {
    std::optional<vk::Buffer> buffer;
    if (source.width > 0) {
      buffer = vk::Buffer::deviceLocal(
          *ctx_, VkDeviceSize(source.width) * source.height * 4,
          VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT, "gradient");
    }
    Run run;
    bool shotTaken = false;
    uint32_t presented = 0;
    const auto begin = std::chrono::steady_clock::now();
    for (uint32_t attempt = 0; presented < frames; ++attempt) {
      if (attempt > frames + 100) throw std::runtime_error("the presenter kept skipping frames");
      window().pollEvents();
      drawPanel(presented);
      const std::optional<app::Frame> frame = presenter_->beginFrame();
      if (!frame) continue;
      run.lastFrame = presented;
      if (presented + 1 == frames) {
        presenter_->requestScreenshot([&](app::Screenshot shot) {
          run.shot = std::move(shot);
          shotTaken = true;
        });
      }
      app::FrameSource frameSource;
      if (buffer) {
        recordUpload(frame->commands, buffer->handle(), gradientImage(source, presented));
        frameSource = {buffer->handle(), 0, source, vk::access::kTransferWrite};
      }
      presenter_->endFrame(frameSource, &*imgui_);
      ++presented;
    }
    const std::chrono::duration<double, std::milli> elapsed =
        std::chrono::steady_clock::now() - begin;
    run.millisecondsPerFrame = elapsed.count() / frames;
    if (!shotTaken) throw std::runtime_error("no screenshot was delivered");
    std::printf("[ timing   ] %u frames of %ux%u on a %ux%u window: %.2f ms per frame\n", frames,
                source.width, source.height, run.shot.width, run.shot.height,
                run.millisecondsPerFrame);
    return run;
  }

  void drawPanel(uint32_t frame) {
    imgui_->newFrame();
    ImGui::SetNextWindowPos(ImVec2(kPanelX, kPanelY));
    ImGui::SetNextWindowSize(ImVec2(kPanelWidth, kPanelHeight));
    ImGui::Begin("presenter smoke", nullptr,
                 ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse |
                     ImGuiWindowFlags_NoSavedSettings);
    ImGui::Text("frame %u", frame);
    ImGui::End();
  }

  // Most pixels inside the panel are the panel's, not the frame's.
  void expectPanelDrawn(const app::Screenshot& shot,
                        const std::function<Rgba(uint32_t, uint32_t)>& frameAt) {
    size_t inside = 0;
    size_t covered = 0;
    for (uint32_t y = 0; y < shot.height; ++y) {
      for (uint32_t x = 0; x < shot.width; ++x) {
        if (!insidePanel(x, y)) continue;
        ++inside;
        if (shot.pixel(x, y) != frameAt(x, y)) ++covered;
      }
    }
    EXPECT_GT(covered, inside * 9 / 10) << "the ImGui panel is missing from the screenshot";
  }

  std::optional<app::FramePresenter> presenter_;
  std::optional<app::ImGuiLayer> imgui_;
};

TEST_F(PresenterTest, SameSizeFrameShowsExactlyOutsideTheOverlay) {
  start();
  const VkExtent2D extent = presenter_->extent();
  ASSERT_EQ(extent.width, 320u);
  ASSERT_EQ(extent.height, 240u);
  const Run run = present(extent, 60);
  const app::Screenshot& shot = run.shot;
  ASSERT_EQ(shot.width, 320u);
  ASSERT_EQ(shot.height, 240u);
  ASSERT_EQ(shot.rgba.size(), 320u * 240u * 4u);

  const Mismatches m = compareOutsidePanel(shot, [&](uint32_t x, uint32_t y, Rgba p) {
    return p == gradient(x, y, extent, run.lastFrame);
  });
  EXPECT_GT(m.compared, 60000u);
  EXPECT_EQ(m.count, 0u) << "pixels differing from frame " << run.lastFrame << "'s gradient, first "
                         << m.first << ", expected "
                         << describe(gradient(0, 0, extent, run.lastFrame)) << " at (0, 0)";
  expectPanelDrawn(shot,
                   [&](uint32_t x, uint32_t y) { return gradient(x, y, extent, run.lastFrame); });

  std::set<uint32_t> colours;
  for (size_t i = 0; i < shot.rgba.size(); i += 4) {
    colours.insert(shot.rgba[i] | shot.rgba[i + 1] << 8 | shot.rgba[i + 2] << 16);
  }
  EXPECT_GT(colours.size(), 1000u);
  EXPECT_EQ(ctx_->validationErrorCount(), 0u);
}

TEST_F(PresenterTest, SmallerFrameIsScaledToFillTheWindow) {
  start();
  const VkExtent2D source{160, 120};
  const Run run = present(source, 5);
  ASSERT_EQ(run.shot.width, 320u);
  ASSERT_EQ(run.shot.height, 240u);
  // Within two levels of the exact bilinear value: the blit filters in fixed point.
  const Mismatches m = compareOutsidePanel(run.shot, [&](uint32_t x, uint32_t y, Rgba p) {
    const auto want = bilinear(x, y, source, {320, 240}, run.lastFrame);
    for (int c = 0; c < 3; ++c) {
      if (std::abs(p[c] - want[c]) > 2.0) return false;
    }
    return true;
  });
  EXPECT_EQ(m.count, 0u) << "pixels off the bilinear scaling, first " << m.first;
}

TEST_F(PresenterTest, WiderFrameIsLetterboxedInTheClearColour) {
  app::PresenterOptions options;
  options.clearColour = {0.0f, 0.0f, 1.0f, 1.0f};
  start(options);
  const VkExtent2D source{320, 120};
  const Run run = present(source, 5);
  ASSERT_EQ(run.shot.height, 240u);
  // Rows 60 to 179 show the frame unscaled; the bars above and below are blue.
  const Mismatches m = compareOutsidePanel(run.shot, [&](uint32_t x, uint32_t y, Rgba p) {
    if (y < 60 || y >= 180) return p == Rgba{0, 0, 255, 255};
    return p == gradient(x, y - 60, source, run.lastFrame);
  });
  EXPECT_EQ(m.count, 0u) << "first " << m.first;
}

TEST_F(PresenterTest, WithoutAFrameTheWindowShowsTheClearColour) {
  app::PresenterOptions options;
  options.clearColour = {1.0f, 0.0f, 0.0f, 1.0f};
  start(options);
  const Run run = present({0, 0}, 3);
  const Mismatches m = compareOutsidePanel(run.shot, [](uint32_t, uint32_t, Rgba p) {
    return p == Rgba{255, 0, 0, 255};
  });
  EXPECT_EQ(m.count, 0u) << "first " << m.first;
  expectPanelDrawn(run.shot, [](uint32_t, uint32_t) { return Rgba{255, 0, 0, 255}; });
}

TEST_F(PresenterTest, ResizingTheWindowRecreatesTheSwapchain) {
  start();
  present(presenter_->extent(), 3);
  window().resize(400, 300);
  for (int attempt = 0; attempt < 200; ++attempt) {
    const VkExtent2D e = presenter_->extent();
    if (e.width == 400 && e.height == 300) break;
    present({0, 0}, 1);
  }
  const VkExtent2D extent = presenter_->extent();
  ASSERT_EQ(extent.width, 400u);
  ASSERT_EQ(extent.height, 300u);
  const Run run = present(extent, 3);
  ASSERT_EQ(run.shot.width, 400u);
  ASSERT_EQ(run.shot.height, 300u);
  const Mismatches m = compareOutsidePanel(run.shot, [&](uint32_t x, uint32_t y, Rgba p) {
    return p == gradient(x, y, extent, run.lastFrame);
  });
  EXPECT_EQ(m.count, 0u) << "first " << m.first;
}

TEST_F(PresenterTest, ImmediateModeIsUsedWhereOffered) {
  uint32_t count = 0;
  ASSERT_EQ(vkGetPhysicalDeviceSurfacePresentModesKHR(ctx_->physicalDevice(), ctx_->surface(),
                                                      &count, nullptr),
            VK_SUCCESS);
  std::vector<VkPresentModeKHR> modes(count);
  ASSERT_EQ(vkGetPhysicalDeviceSurfacePresentModesKHR(ctx_->physicalDevice(), ctx_->surface(),
                                                      &count, modes.data()),
            VK_SUCCESS);
  const bool offered =
      std::find(modes.begin(), modes.end(), VK_PRESENT_MODE_IMMEDIATE_KHR) != modes.end();

  app::PresenterOptions options;
  options.presentMode = app::PresentMode::Immediate;
  options.framesInFlight = 3;
  start(options);
  EXPECT_EQ(presenter_->swapchain().presentMode(),
            offered ? VK_PRESENT_MODE_IMMEDIATE_KHR : VK_PRESENT_MODE_FIFO_KHR);
  const VkExtent2D extent = presenter_->extent();
  const Run run = present(extent, 60);
  const Mismatches m = compareOutsidePanel(run.shot, [&](uint32_t x, uint32_t y, Rgba p) {
    return p == gradient(x, y, extent, run.lastFrame);
  });
  EXPECT_EQ(m.count, 0u) << "first " << m.first;
}

}  // namespace
}  // namespace amrstream::testing
