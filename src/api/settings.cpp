#include "amrstream/settings.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>

namespace amrstream {

std::string shownDefault(const Setting& setting) {
  if (!setting.shown.empty()) return std::string(setting.shown);
  const double x = setting.fallback;
  if (x == 0.0) return {};
  return x == std::floor(x) && std::abs(x) < 1e15 ? fmt::format("{:.0f}", x)
                                                  : fmt::format("{:g}", x);
}

std::span<const Setting* const> allSettings() {
  using namespace settings;
  static constexpr std::array all{&kLevels,
                                  &kRootBlocks,
                                  &kTargetCells,
                                  &kGenSeed,
                                  &kTime,
                                  &kLengthUnit,
                                  &kUnit,
                                  &kVector,
                                  &kFrameVelocity,
                                  &kPointData,
                                  &kPeriodic,
                                  &kInterpolant,
                                  &kSeeds,
                                  &kSeedBox,
                                  &kSeedLine,
                                  &kSeedGrid,
                                  &kSeedDensity,
                                  &kSeedPercentile,
                                  &kSeedWeighted,
                                  &kSeedsOut,
                                  &kCount,
                                  &kSeed,
                                  &kSteps,
                                  &kStepSize,
                                  &kStepMode,
                                  &kIntegrator,
                                  &kTolerance,
                                  &kMinStep,
                                  &kMaxStep,
                                  &kDirection,
                                  &kVorticity,
                                  &kTerminalSpeed,
                                  &kMaxLength,
                                  &kMaxTime,
                                  &kMemoryBudget,
                                  &kCpuTail,
                                  &kBackend,
                                  &kDevice,
                                  &kCompression,
                                  &kPeriodicLines,
                                  &kStartTime,
                                  &kEndTime,
                                  &kTimeStep,
                                  &kReleaseEvery,
                                  &kWidth,
                                  &kHeight,
                                  &kFrames,
                                  &kAoSamples,
                                  &kCamera,
                                  &kView,
                                  &kZoom,
                                  &kUp,
                                  &kFov,
                                  &kProjection,
                                  &kFrame,
                                  &kLookAt,
                                  &kViewBox,
                                  &kTubeRadius,
                                  &kTubeRadiusPhysical,
                                  &kTubeRadiusView,
                                  &kRadiusByColour,
                                  &kColourBy,
                                  &kColourMap,
                                  &kColourScale,
                                  &kSymlogWidth,
                                  &kRange,
                                  &kOutline,
                                  &kAxes,
                                  &kTriad,
                                  &kScaleBar,
                                  &kBackground,
                                  &kVolume,
                                  &kVolumeRange,
                                  &kVolumeOpacity,
                                  &kLinearVolume,
                                  &kColourBar};
  return all;
}

}  // namespace amrstream
