#pragma once
// A slice figure: a plane through the data with a channel reconstructed on it, the field lines of
// the vector's part in the plane, evenly spaced, and optionally a line integral convolution (LIC)
// texture of it, written as a PNG (and the plane's samples as .vti).

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "amrstream/backend.hpp"
#include "amrstream/field.hpp"
#include "amrstream/log.hpp"
#include "amrstream/rendering.hpp"
#include "amrstream/trace_job.hpp"

namespace amrstream {

// What a slice shows (the command line's options of the same names).
struct SliceOptions {
  std::string normal = "z";                     // x, y, z, or NX,NY,NZ
  std::optional<std::array<double, 3>> point;   // default: the domain's centre
  std::optional<std::array<double, 4>> window;  // a0,b0,a1,b1 in the plane; default: the domain
  std::uint32_t width = 1024;                   // pixels across; the height in proportion
  // A channel, "magnitude" (the vector's), "none", or "auto": a density channel (dens, density,
  // rho, any case) where there is one, else the magnitude.
  std::string background = "auto";
  std::string colourMap = "viridis";
  std::string colourScale = "linear";          // linear, log or symlog
  std::optional<std::array<double, 2>> range;  // of the background; default: its own
  bool lines = true;
  double lineSeparation = 0.0;  // in the plane's coordinates; 0: 1/30 of the window's width
  float lineWidth = 1.5f;       // pixels; with lineWidthBy, the widest
  // A channel or "magnitude" (the vector's length) along the lines that colours them, in
  // lineColourMap on lineColourScale (linear, log or symlog); empty: black lines.
  std::string lineColourBy;
  std::string lineColourMap = "plasma";
  std::string lineColourScale = "linear";
  // A channel or "magnitude" that the lines' width follows, from a fifth of lineWidth at its
  // least along the lines to lineWidth at its most; empty: lineWidth throughout.
  std::string lineWidthBy;
  bool lic = false;
  double licLength = 0.0;  // the LIC kernel's half-length, in the plane's coordinates; 0: 1/50
                           // of the window's width
  // Where the LIC runs: a GPU backend samples the plane and convolves on the device; `auto` as
  // for tracing (the CPU where the only device is a software one).
  BackendRequest backend;
};

// A slice as drawn: the figure and what it shows, for callers that want the numbers.
struct SliceFigure {
  Image image;                          // the figure, RGBA
  std::uint32_t width = 0, height = 0;  // the window's pixels (the arrays' shape)
  std::array<double, 4> window{};       // a0, b0, a1, b1
  std::array<std::string, 2> axes;      // the plane's axes' names: "x", "y", ... or "a", "b"
  std::string backgroundName;           // empty: none
  std::vector<float> background;        // width x height, x fastest, row 0 at b0; NaN: no data
  std::vector<float> lic;               // the same; empty without LIC
  std::vector<std::vector<std::array<double, 2>>> lines;  // in the plane's coordinates
  // Per line, per point: the values the lines are coloured by and their width follows; empty
  // when not asked for. NaN where a point has no data.
  std::vector<std::vector<float>> lineColourValues, lineWidthValues;
};

struct SliceJob {
  DatasetRequest dataset;
  FieldOptions field;
  SliceOptions slice;
  std::string out = "slice.png";
  std::string vti;  // the plane's samples (vector, channels, LIC) as VTK ImageData; empty: none
  // The field lines as VTK PolyData polylines on the plane (physical coordinates) with the
  // vector, every point-data channel and the arc length along them; empty: none.
  std::string vtp;
};

// Throws InputError naming the option for a value out of its range.
void checkSliceOptions(const SliceOptions& options);

// Samples the plane in `field`, traces its lines and convolves its LIC as `options` say, and
// draws the figure. Says the "plane", "lines" and "lic" lines (and "backend" for auto with LIC);
// progress: stage "slicing", rows. Throws vk::ContextError where the device lacks the backend.
SliceFigure makeSlice(const Field& field, const SliceOptions& options,
                      const Reporter& reporter = {});

// The checks made before any work: the builtin dataset's size and the options' values.
void checkSliceJob(const SliceJob& job);

// Loads, builds the field, samples the plane, draws the figure and writes the files. Says the
// "input", "structure", "plane", "lines", "lic" and "output" lines; progress: stage "slicing",
// rows.
void runSliceJob(const SliceJob& job, const Reporter& reporter = {});

}  // namespace amrstream
