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
  auto* camera = command
                     .add_option("--camera", o.camera,
                                 "AZIMUTH,ELEVATION[,ZOOM]: degrees about the up axis and above "
                                 "the plane across it, and a zoom factor (> 1 closer) "
                                 "[default 35,25,1]")
                     ->delimiter(',')
                     ->expected(2, 3)
                     ->check(finiteFloat());
  command
      .add_option("--view", o.view,
                  "look from a named direction: iso, +x, -x, +y, -y, +z or -z (+x looks from "
                  "+x towards -x)")
      ->check(CLI::IsMember({"iso", "+x", "-x", "+y", "-y", "+z", "-z"}))
      ->excludes(camera);
  command.add_option("--zoom", o.zoom, "zoom factor after framing (> 1 closer)")
      ->capture_default_str()
      ->check(positiveFloat());
  command.add_option("--up", o.up, "the axis that points up on screen: +x, -x, +y, -y, +z, -z")
      ->capture_default_str()
      ->check(CLI::IsMember({"+x", "-x", "+y", "-y", "+z", "-z", "x", "y", "z"}));
  command.add_option("--fov", o.fovDegrees, "vertical field of view in degrees (1 to 150)")
      ->capture_default_str()
      ->check(CLI::Range(1.0f, 150.0f));
  command
      .add_option("--projection", o.projection,
                  "perspective, or orthographic (parallel rays: sizes do not shrink with depth)")
      ->capture_default_str()
      ->check(CLI::IsMember({"perspective", "orthographic"}));
  command
      .add_option("--frame", o.frame,
                  "what the camera frames: traces (their tubes' bounding box) or domain")
      ->capture_default_str()
      ->check(CLI::IsMember({"traces", "domain"}));
  command
      .add_option("--look-at", o.lookAt,
                  "x,y,z the camera looks at (it stays far enough to see the framed box) "
                  "[default: the framed box's centre]")
      ->delimiter(',')
      ->expected(3)
      ->check(finiteFloat());
  command
      .add_option("--view-box", o.viewBox,
                  "x0,y0,z0,x1,y1,z1: the box the camera frames [default: see --frame]")
      ->delimiter(',')
      ->expected(6)
      ->check(finiteFloat());
  auto* cells = command.add_option("--tube-radius", o.tubeRadius, "tube radius in finest cells")
                    ->check(positiveFloat());
  auto* physical = command
                       .add_option("--tube-radius-physical", o.tubeRadiusPhysical,
                                   "tube radius in the input's length units")
                       ->check(positiveFloat())
                       ->excludes(cells);
  command
      .add_option("--tube-radius-view", o.tubeRadiusOfView,
                  "without the two above: tube radius as a fraction of the view's height, so "
                  "tubes look alike whatever the data's depth and size (0 to 0.5)")
      ->capture_default_str()
      ->check(CLI::Range(1e-6f, 0.5f))
      ->excludes(cells)
      ->excludes(physical);
  command
      .add_option("--radius-by-colour", o.radiusByColour,
                  "tubes as thick as the colour field is high: this fraction of the radius at "
                  "the colour range's low end, the whole radius at its high end (0 to 1; 1: "
                  "one radius)")
      ->capture_default_str()
      ->check(CLI::Range(1e-6f, 1.0f));
  command
      .add_option("--colour-by", o.colourBy,
                  "speed, time (IntegrationTime) or a scalar channel sampled along the tubes")
      ->capture_default_str();
  command.add_option("--colour-map", o.colourMap, render::colourMapNames())->capture_default_str();
  command
      .add_option("--colour-scale", o.colourScale,
                  "how values map onto the colour map: linear, log (positive values; the rest "
                  "take the low end) or symlog (linear near 0, log beyond, both signs)")
      ->capture_default_str()
      ->check(CLI::IsMember({"linear", "log", "symlog"}));
  command
      .add_option("--symlog-width", o.symlogWidth,
                  "symlog's linear part: -W..W [default: 1/1000 of the largest magnitude]")
      ->check(positiveFloat());
  command
      .add_option("--range", o.range,
                  "MIN,MAX of the colour field [default: its range; the positive values' "
                  "with --colour-scale log]")
      ->delimiter(',')
      ->expected(2)
      ->check(finiteFloat());
  command
      .add_option("--outline", o.outline,
                  "thin tubes along the domain's edges (domain), every brick's (bricks) or none")
      ->capture_default_str()
      ->check(CLI::IsMember({"domain", "bricks", "none"}));
  command.add_flag("--axes", o.axes,
                   "the domain's axes, with ticks and labels in physical units, along the edges "
                   "on the outside of its outline (zooms out a little to make room)");
  command.add_flag("!--no-triad", o.triad, "leave out the orientation triad (bottom left)");
  command.add_flag("--scale-bar", o.scaleBar,
                   "a bar of a round physical length, exact in orthographic views, at the framed "
                   "centre's depth in perspective");
  command.add_option("--background", o.background,
                     "a flat background: white, black, #rrggbb or R,G,B from 0 to 1, or "
                     "transparent (a PNG whose alpha is the coverage) [default: a dark grey "
                     "gradient]");
  command
      .add_option("--ao-samples", o.aoSamples,
                  "ambient-occlusion rays per pixel and frame (0: off)")
      ->capture_default_str()
      ->check(countIn(0, kMaxAoSamples));
  command.add_option("--volume", o.volume,
                     "a scalar channel to show as a volume behind the tubes, e.g. dens");
  command
      .add_option("--volume-range", o.volumeRange,
                  "MIN,MAX of the transfer function, in log10 unless --linear-volume "
                  "[default: the median to the 99.9th percentile]")
      ->delimiter(',')
      ->expected(2)
      ->check(finiteFloat());
  command
      .add_option("--volume-opacity", o.volumeOpacity,
                  "extinction per finest cell at the top of the transfer function")
      ->capture_default_str()
      ->check(nonNegativeFloat());
  command.add_flag("--linear-volume", o.linearVolume,
                   "map the volume's scalar linearly instead of its log10");
}

}  // namespace amrstream::cli
