#pragma once
// Every setting a user gives the library, stated once: its neutral name, what it means, its
// default and the range of its values. The request structs take their defaults from here, the
// library checks values against the ranges and names a setting neutrally in its errors, and the
// front ends spell the names their own way: the command line `--name-with-dashes`, Python
// `name_with_underscores` (the neutral name itself). Texts name other settings as `{name}`, which
// spellSettings() spells for a front end. docs/cli.md and docs/python.md show the same defaults,
// which a test compares with these.

#include <cstdint>
#include <functional>
#include <limits>
#include <span>
#include <string>
#include <string_view>

#include "amrstream/error.hpp"

namespace amrstream {

struct Setting {
  std::string_view name;  // neutral: snake_case
  std::string_view help;  // what it means, naming other settings as {name}
  double fallback = 0.0;  // a number's default
  // A text's default value, or a number's where it is 0 (a number's other defaults are
  // `fallback`). Empty: no default value (off, or chosen from the data as `help` says).
  std::string_view shown = {};
  double least = -std::numeric_limits<double>::infinity();  // the closed range of a number
  double most = std::numeric_limits<double>::infinity();
  bool positive = false;          // a number must be > 0 (and at least the type's smallest normal)
  std::string_view choices = {};  // "a|b|c" where the values are fixed
};

// The default value as help texts and the docs show it: `shown`, else a non-zero `fallback`
// ("1000", "0.0001"); empty where there is none.
std::string shownDefault(const Setting& setting);

namespace settings {

inline constexpr double kFloatMax = std::numeric_limits<float>::max();

// The dataset (builtin:KIND inputs).
inline constexpr Setting kLevels{.name = "levels",
                                 .help = "AMR levels of a generated dataset",
                                 .fallback = 5,
                                 .least = 1,
                                 .most = 8};
inline constexpr Setting kRootBlocks{
    .name = "root_blocks",
    .help = "root blocks (of 8^3 cells) per axis of a generated dataset",
    .fallback = 4,
    .least = 1,
    .most = std::numeric_limits<int>::max()};
inline constexpr Setting kTargetCells{.name = "target_cells",
                                      .help = "cell budget of a generated dataset",
                                      .fallback = 1'000'000,
                                      .least = 1,
                                      .most = 2'147'483'647};
inline constexpr Setting kGenSeed{
    .name = "gen_seed", .help = "random seed of a generated dataset", .fallback = 1, .least = 0};
inline constexpr Setting kTime{
    .name = "time", .help = "snapshot time of a generated unsteady dataset (swirl)", .shown = "0"};

// Units the input does not state.
inline constexpr Setting kLengthUnit{
    .name = "length_unit",
    .help =
        "the unit of the input's coordinates where the file states none, e.g. cm: shown on "
        "axes and scale bars and written with the traces"};
inline constexpr Setting kUnit{
    .name = "unit",
    .help =
        "NAME=UNIT: the unit of a channel (or of the vector, by its name) where the file "
        "states none, e.g. density=g/cm**3; shown on colour bars; repeat for several"};

// The field.
inline constexpr Setting kVector{
    .name = "vector",
    .help =
        "three channels forming the vector, e.g. velx,vely,velz, or grad(NAME) or -grad(NAME): "
        "the gradient of the scalar channel NAME per unit length, or its negative (default: the "
        "velocity, else the magnetic field)",
    .shown = ""};
inline constexpr Setting kFrameVelocity{
    .name = "frame_velocity",
    .help =
        "VX,VY,VZ subtracted from the vector (a velocity relative to a frame moving at it), or "
        "auto: the vector's mean over the seeding region, weighted by cell volume",
    .shown = ""};
inline constexpr Setting kPointData{.name = "point_data",
                                    .help =
                                        "channels sampled at every trace point: all (every "
                                        "channel but the vector's), none, or NAME,NAME,...",
                                    .shown = "all"};
inline constexpr Setting kPeriodic{
    .name = "periodic",
    .help = "periodic axes: auto (as the file says), none, or a list such as x,y,z",
    .shown = "auto"};
inline constexpr Setting kInterpolant{
    .name = "interpolant",
    .help =
        "tent: the paper's tent basis functions (exact for constants); linear: tent weights "
        "over each cell's least-squares linear model (exact for linear fields across level "
        "jumps)",
    .shown = "tent",
    .choices = "tent|linear"};

// The seeds.
inline constexpr Setting kSeeds{.name = "seeds",
                                .help = "file of seed points, one 'x y z' per line"};
inline constexpr Setting kSeedBox{
    .name = "seed_box",
    .help = "random seeds in this box: x0,y0,z0,x1,y1,z1 (default: the domain)",
    .least = -kFloatMax,
    .most = kFloatMax};
inline constexpr Setting kSeedLine{.name = "seed_line",
                                   .help = "a rake of {count} seeds from x0,y0,z0 to x1,y1,z1",
                                   .least = -kFloatMax,
                                   .most = kFloatMax};
inline constexpr Setting kSeedGrid{
    .name = "seed_grid",
    .help =
        "a regular NX,NY,NZ grid in the seed box instead of random seeds (a box of zero "
        "thickness with count 1 on that axis is a plane)",
    .least = 1,
    .most = 2'147'483'647};
inline constexpr Setting kSeedDensity{
    .name = "seed_density",
    .help =
        "the paper's seeding: random points in random cells where this scalar is at or above "
        "{seed_percentile}"};
inline constexpr Setting kSeedPercentile{.name = "seed_percentile",
                                         .help = "see {seed_density}",
                                         .fallback = 90,
                                         .least = 0,
                                         .most = 100};
inline constexpr Setting kSeedWeighted{
    .name = "seed_weighted",
    .help = "with {seed_density}: pick cells with probability proportional to the scalar"};
inline constexpr Setting kSeedsOut{
    .name = "seeds_out",
    .help = "write the seeds used to this file, so the run can be repeated with {seeds}"};
inline constexpr Setting kCount{
    .name = "count",
    .help = "number of seeds (random, along {seed_line}, or of {seed_density})",
    .fallback = 256,
    .least = 1,
    .most = 2'147'483'647};
inline constexpr Setting kSeed{
    .name = "seed", .help = "random seed for the seed points", .fallback = 1, .least = 0};

// The stepping.
inline constexpr Setting kSteps{.name = "steps",
                                .help = "maximum integration steps per trace",
                                .fallback = 1000,
                                .least = 0,
                                .most = 1'000'000'000};
inline constexpr Setting kStepSize{
    .name = "step_size",
    .help =
        "h: in cell widths (cell, arc) or physical time (time; default 1/4 of the finest cell "
        "crossed at the maximum speed)",
    .fallback = 0.25,
    .most = kFloatMax,
    .positive = true};
inline constexpr Setting kStepMode{
    .name = "step_mode",
    .help =
        "arc: steps of h cell widths whatever the speed; cell: the paper's, on w(x)v(x), so h "
        "depends on the vector's units; time: fixed dt",
    .shown = "arc",
    .choices = "cell|time|arc"};
inline constexpr Setting kIntegrator{
    .name = "integrator",
    .help = "rk4 (the paper's), rk45 (Dormand-Prince with error control), rk2 or euler",
    .shown = "rk4",
    .choices = "rk4|rk45|rk2|euler"};
inline constexpr Setting kTolerance{
    .name = "tolerance",
    .help = "rk45: the error allowed per step, in finest cell widths of its region",
    .fallback = 1e-4,
    .least = 1e-8,
    .most = 1};
inline constexpr Setting kMinStep{
    .name = "min_step",
    .help = "rk45: the smallest step, in {step_size}'s units [default: the first step / 100]",
    .most = kFloatMax,
    .positive = true};
inline constexpr Setting kMaxStep{
    .name = "max_step",
    .help = "rk45: the largest step, in {step_size}'s units [default: the first step x 4]",
    .most = kFloatMax,
    .positive = true};
inline constexpr Setting kDirection{
    .name = "direction",
    .help =
        "integration direction: forward, backward, or both (two lines per seed, as "
        "ParaView's Stream Tracer)",
    .shown = "both",
    .choices = "forward|backward|both"};
inline constexpr Setting kVorticity{
    .name = "vorticity",
    .help = "also write Vorticity, Rotation and AngularVelocity (as vtkStreamTracer)"};
inline constexpr Setting kTerminalSpeed{.name = "terminal_speed",
                                        .help = "stop where the speed falls below this",
                                        .fallback = 1e-12,
                                        .least = 0,
                                        .most = kFloatMax};
inline constexpr Setting kMaxLength{
    .name = "max_length",
    .help = "stop before the trace's physical length passes this (0: no limit)",
    .shown = "0",
    .least = 0,
    .most = kFloatMax};
inline constexpr Setting kMaxTime{
    .name = "max_time",
    .help =
        "stop where |IntegrationTime| reaches this, the last step shortened to end on it "
        "(0: no limit)",
    .shown = "0",
    .least = 0,
    .most = kFloatMax};
inline constexpr Setting kMemoryBudget{
    .name = "memory_budget",
    .help =
        "bytes the tracing rounds may use (a GPU's round buffers, or the CPU's), e.g. 512M "
        "or 2G (the collected traces come on top); 0: automatic, 256M to 8G on a GPU, 2G on "
        "the CPU; at most the machine's memory",
    .shown = "0",
    .least = 0};
inline constexpr Setting kCpuTail{
    .name = "cpu_tail",
    .help =
        "on a GPU: once a round leaves this many running lines or fewer, the CPU finishes "
        "them on all cores (a lone line's step is faster there); 0: never. Without history "
        "the GPU then runs rounds of an eighth of {steps}, at least 1000; the points wait in "
        "host memory",
    .shown = "0",
    .least = 0,
    .most = 2'147'483'647};

// Where it runs.
inline constexpr Setting kBackend{
    .name = "backend",
    .help =
        "auto (rayquery, else pipeline, else compute, else cpu), rayquery, pipeline, compute "
        "or cpu",
    .shown = "auto",
    .choices = "auto|rayquery|pipeline|compute|cpu"};
inline constexpr Setting kDevice{
    .name = "device",
    .help = "the Vulkan device whose name contains this (see `amrstream devices`)"};

// The written lines.
inline constexpr Setting kCompression{
    .name = "compression",
    .help =
        "compression of the .vtp's arrays: zlib (as VTK and ParaView write), lz4 (faster, "
        "larger) or none",
    .shown = "zlib",
    .choices = "none|zlib|lz4"};
inline constexpr Setting kPeriodicLines{
    .name = "periodic_lines",
    .help =
        "lines crossing a periodic face: split (one polyline per piece inside the domain) or "
        "unwrapped (one polyline continuing past the face)",
    .shown = "split",
    .choices = "split|unwrapped"};

// Pathlines.
inline constexpr Setting kStartTime{.name = "start_time",
                                    .help =
                                        "release the particles at this time (default: the first "
                                        "snapshot's)",
                                    .least = -std::numeric_limits<double>::max(),
                                    .most = std::numeric_limits<double>::max()};
inline constexpr Setting kEndTime{
    .name = "end_time",
    .help = "stop the particles at this time (default: the last snapshot's)",
    .least = -std::numeric_limits<double>::max(),
    .most = std::numeric_limits<double>::max()};
inline constexpr Setting kTimeStep{
    .name = "step_size",
    .help =
        "RK4 time step (default: a tenth of the shortest interval between the snapshots "
        "used); steps end on every snapshot's time",
    .most = std::numeric_limits<double>::max(),
    .positive = true};
inline constexpr Setting kReleaseEvery{
    .name = "release_every",
    .help =
        "release new particles from the seeds at this interval and write streaklines (one "
        "line per seed through its particles at the end time)",
    .most = std::numeric_limits<double>::max(),
    .positive = true};

// Rendering.
inline constexpr Setting kWidth{
    .name = "width", .help = "image width in pixels", .fallback = 1024, .least = 16, .most = 16384};
inline constexpr Setting kHeight{.name = "height",
                                 .help = "image height in pixels",
                                 .fallback = 768,
                                 .least = 16,
                                 .most = 16384};
inline constexpr Setting kFrames{
    .name = "frames",
    .help =
        "frames accumulated: jittered samples per pixel, each with {ao_samples} occlusion "
        "rays",
    .fallback = 32,
    .least = 1,
    .most = 4096};
inline constexpr Setting kAoSamples{.name = "ao_samples",
                                    .help = "ambient-occlusion rays per pixel and frame (0: off)",
                                    .fallback = 4,
                                    .least = 0,
                                    .most = 256};
inline constexpr Setting kCamera{
    .name = "camera",
    .help =
        "AZIMUTH,ELEVATION[,ZOOM]: degrees about the up axis and above the plane across it, "
        "and a zoom factor (> 1 closer)",
    .shown = "35,25,1",
    .least = -kFloatMax,
    .most = kFloatMax};
// The bounds of camera's angles, in degrees: an azimuth within a turn either way reaches every
// direction about the up axis (larger ones only lose precision in float), and an elevation from
// straight below the framed centre to straight above it.
inline constexpr double kMaxCameraAzimuth = 360;
inline constexpr double kMaxCameraElevation = 90;
inline constexpr Setting kView{
    .name = "view",
    .help =
        "look from a named direction: iso, +x, -x, +y, -y, +z or -z (+x looks from +x "
        "towards -x)",
    .choices = "iso|+x|-x|+y|-y|+z|-z"};
inline constexpr Setting kZoom{.name = "zoom",
                               .help = "zoom factor after framing (> 1 closer)",
                               .fallback = 1,
                               .most = kFloatMax,
                               .positive = true};
inline constexpr Setting kUp{.name = "up",
                             .help = "the axis that points up on screen: +x, -x, +y, -y, +z, -z",
                             .shown = "+z",
                             .choices = "+x|-x|+y|-y|+z|-z|x|y|z"};
inline constexpr Setting kFov{.name = "fov",
                              .help = "vertical field of view in degrees (1 to 150)",
                              .fallback = 35,
                              .least = 1,
                              .most = 150};
inline constexpr Setting kProjection{
    .name = "projection",
    .help = "perspective, or orthographic (parallel rays: sizes do not shrink with depth)",
    .shown = "perspective",
    .choices = "perspective|orthographic"};
inline constexpr Setting kFrame{
    .name = "frame",
    .help = "what the camera frames: traces (their tubes' bounding box) or domain",
    .shown = "traces",
    .choices = "traces|domain"};
inline constexpr Setting kLookAt{
    .name = "look_at",
    .help =
        "x,y,z the camera looks at (it stays far enough to see the framed box) [default: the "
        "framed box's centre]",
    .least = -kFloatMax,
    .most = kFloatMax};
inline constexpr Setting kViewBox{
    .name = "view_box",
    .help = "x0,y0,z0,x1,y1,z1: the box the camera frames [default: see {frame}]",
    .least = -kFloatMax,
    .most = kFloatMax};
inline constexpr Setting kTubeRadius{.name = "tube_radius",
                                     .help = "tube radius in finest cells",
                                     .most = kFloatMax,
                                     .positive = true};
inline constexpr Setting kTubeRadiusPhysical{.name = "tube_radius_physical",
                                             .help = "tube radius in the input's length units",
                                             .most = kFloatMax,
                                             .positive = true};
inline constexpr Setting kTubeRadiusView{
    .name = "tube_radius_view",
    .help =
        "without the two above: tube radius as a fraction of the view's height, so tubes "
        "look alike whatever the data's depth and size (0 to 0.5)",
    .fallback = 0.003,
    .least = 1e-6,
    .most = 0.5};
inline constexpr Setting kRadiusByColour{
    .name = "radius_by_colour",
    .help =
        "tubes as thick as the colour field is high: this fraction of the radius at the "
        "colour range's low end, the whole radius at its high end (0 to 1; 1: one radius)",
    .fallback = 1,
    .least = 1e-6,
    .most = 1};
inline constexpr Setting kColourBy{
    .name = "colour_by",
    .help = "speed, time (IntegrationTime) or a scalar channel sampled along the tubes",
    .shown = "speed"};
inline constexpr Setting kColourMap{
    .name = "colour_map", .help = "the colour map", .shown = "viridis"};
inline constexpr Setting kColourScale{
    .name = "colour_scale",
    .help =
        "how values map onto the colour map: linear, log (positive values; the rest take the "
        "low end) or symlog (linear near 0, log beyond, both signs)",
    .shown = "linear",
    .choices = "linear|log|symlog"};
inline constexpr Setting kSymlogWidth{
    .name = "symlog_width",
    .help = "symlog's linear part: -W..W [default: 1/1000 of the largest magnitude]",
    .most = kFloatMax,
    .positive = true};
inline constexpr Setting kRange{
    .name = "range",
    .help =
        "MIN,MAX of the colour field [default: its range; the positive values' with "
        "{colour_scale} log]",
    .least = -kFloatMax,
    .most = kFloatMax};
inline constexpr Setting kOutline{
    .name = "outline",
    .help =
        "thin tubes along the domain's edges (domain), every brick's (bricks) or none; "
        "auto: the domain's, unless {axes} are drawn around the traces or {view_box}",
    .shown = "auto",
    .choices = "auto|domain|bricks|none"};
inline constexpr Setting kAxes{
    .name = "axes",
    .help =
        "the domain's axes, with ticks and labels in physical units, along the edges on the "
        "outside of its outline (zooms out a little to make room)"};
inline constexpr Setting kTriad{.name = "triad", .help = "the orientation triad (bottom left)"};
inline constexpr Setting kScaleBar{
    .name = "scale_bar",
    .help =
        "a bar of a round physical length, exact in orthographic views, at the framed "
        "centre's depth in perspective"};
inline constexpr Setting kBackground{
    .name = "background",
    .help =
        "a flat background: white, black, #rrggbb or R,G,B from 0 to 1, or transparent (a "
        "PNG whose alpha is the coverage) [default: a dark grey gradient]"};
inline constexpr Setting kVolume{
    .name = "volume", .help = "a scalar channel to show as a volume behind the tubes, e.g. dens"};
inline constexpr Setting kVolumeRange{
    .name = "volume_range",
    .help =
        "MIN,MAX of the transfer function, in log10 unless {linear_volume} [default: from the "
        "value most of the domain holds to the 99.9th percentile of the cells]",
    .least = -kFloatMax,
    .most = kFloatMax};
inline constexpr Setting kVolumeOpacity{.name = "volume_opacity",
                                        .help =
                                            "extinction per finest cell at the top of the transfer "
                                            "function; 0: chosen so that a ray across the domain "
                                            "is absorbed to 1 - 1/e on average",
                                        .fallback = 0,
                                        .least = 0,
                                        .most = kFloatMax};
inline constexpr Setting kLinearVolume{
    .name = "linear_volume", .help = "map the volume's scalar linearly instead of its log10"};
inline constexpr Setting kColourBar{.name = "colour_bar", .help = "the colour bar"};

}  // namespace settings

// Every setting above, for front ends that list or check them.
std::span<const Setting* const> allSettings();

}  // namespace amrstream
