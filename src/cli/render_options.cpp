#include "render_options.hpp"

#include "amrstream/settings.hpp"
#include "option_checks.hpp"
#include "setting_options.hpp"

namespace amrstream::cli {

namespace s = settings;

void addRenderOptions(CLI::App& command, RenderOptions& o) {
  addSetting(command, s::kWidth, o.width);
  addSetting(command, s::kHeight, o.height);
  auto* camera =
      addSetting(command, s::kCamera, o.camera)
          ->delimiter(',')
          ->expected(2, 3)
          ->check(numberIn(-s::kMaxCameraAzimuth, s::kMaxCameraAzimuth).application_index(0))
          ->check(numberIn(-s::kMaxCameraElevation, s::kMaxCameraElevation).application_index(1));
  addSetting(command, s::kView, o.view)->excludes(camera);
  addSetting(command, s::kZoom, o.zoom);
  addSetting(command, s::kUp, o.up);
  addSetting(command, s::kFov, o.fovDegrees);
  addSetting(command, s::kProjection, o.projection);
  addSetting(command, s::kFrame, o.frame);
  addSetting(command, s::kLookAt, o.lookAt)->delimiter(',')->expected(3);
  addSetting(command, s::kViewBox, o.viewBox)->delimiter(',')->expected(6);
  auto* cells = addSetting(command, s::kTubeRadius, o.tubeRadius);
  auto* physical =
      addSetting(command, s::kTubeRadiusPhysical, o.tubeRadiusPhysical)->excludes(cells);
  addSetting(command, s::kTubeRadiusView, o.tubeRadiusOfView)->excludes(cells)->excludes(physical);
  addSetting(command, s::kRadiusByColour, o.radiusByColour);
  addSetting(command, s::kColourBy, o.colourBy);
  command.add_option(cliFlag(s::kColourMap.name), o.colourMap, colourMapNames())
      ->default_str(shownDefault(s::kColourMap));
  addSetting(command, s::kColourScale, o.colourScale);
  addSetting(command, s::kSymlogWidth, o.symlogWidth);
  addSetting(command, s::kRange, o.range)->delimiter(',')->expected(2);
  addSetting(command, s::kOutline, o.outline);
  addSetting(command, s::kAxes, o.axes);
  command.add_flag_callback(
      "--no-triad", [&o] { o.triad = false; }, "leave out " + settingHelp(s::kTriad));
  addSetting(command, s::kScaleBar, o.scaleBar);
  addSetting(command, s::kBackground, o.background);
  addSetting(command, s::kAoSamples, o.aoSamples);
  addSetting(command, s::kVolume, o.volume);
  addSetting(command, s::kVolumeRange, o.volumeRange)->delimiter(',')->expected(2);
  addSetting(command, s::kVolumeOpacity, o.volumeOpacity);
  addSetting(command, s::kLinearVolume, o.linearVolume);
}

}  // namespace amrstream::cli
