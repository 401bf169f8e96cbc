#include "render_options.hpp"

#include "option_checks.hpp"
#include "option_limits.hpp"

namespace amrstream::cli {

void addRenderOptions(CLI::App& command, RenderOptions& o) {
  command.add_option("--width", o.width, "image width in pixels")
      ->capture_default_str()
      ->check(countIn(kMinImageSide, kMaxImageSide));
  command.add_option("--height", o.height, "image height in pixels")
      ->capture_default_str()
      ->check(countIn(kMinImageSide, kMaxImageSide));
  command.add_option("--camera", o.camera,
                     "AZIMUTH,ELEVATION[,ZOOM]: degrees about +z and above the xy plane, and a "
                     "zoom factor (> 1 closer) [default 35,25,1]")
      ->delimiter(',')
      ->expected(2, 3)
      ->check(finiteFloat());
  command.add_option("--view-box", o.viewBox,
                     "x0,y0,z0,x1,y1,z1: the box the camera frames [default: the domain]")
      ->delimiter(',')
      ->expected(6)
      ->check(finiteFloat());
  command.add_option("--tube-radius", o.tubeRadius,
                     "tube radius in finest cells [default 0.5, or 1/1200 of the domain's "
                     "diagonal when larger]")
      ->check(positiveFloat());
  command.add_option("--colour-by", o.colourBy,
                     "speed, time (IntegrationTime) or a scalar channel sampled along the tubes")
      ->capture_default_str();
  command.add_option("--colour-map", o.colourMap, "viridis, magma or coolwarm")->capture_default_str();
  command.add_option("--range", o.range, "MIN,MAX of the colour field [default: its range]")
      ->delimiter(',')
      ->expected(2)
      ->check(finiteFloat());
  command.add_option("--ao-samples", o.aoSamples,
                     "ambient-occlusion rays per pixel and frame (0: off)")
      ->capture_default_str()
      ->check(countIn(0, kMaxAoSamples));
  command.add_option("--volume", o.volume,
                     "a scalar channel to show as a volume behind the tubes, e.g. dens");
  command.add_option("--volume-range", o.volumeRange,
                     "MIN,MAX of the transfer function, in log10 unless --linear-volume "
                     "[default: the median to the 99.9th percentile]")
      ->delimiter(',')
      ->expected(2)
      ->check(finiteFloat());
  command.add_option("--volume-opacity", o.volumeOpacity,
                     "extinction per finest cell at the top of the transfer function")
      ->capture_default_str()
      ->check(nonNegativeFloat());
  command.add_flag("--linear-volume", o.linearVolume,
                   "map the volume's scalar linearly instead of its log10");
}

}  // namespace amrstream::cli
