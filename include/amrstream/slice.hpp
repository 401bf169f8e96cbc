#pragma once
// A slice figure: a plane through the data with a channel reconstructed on it, the field lines of
// the vector's part in the plane, evenly spaced, and optionally a line integral convolution (LIC)
// texture of it, written as a PNG (and the plane's samples as .vti).

#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include "amrstream/field.hpp"
#include "amrstream/log.hpp"
#include "amrstream/trace_job.hpp"

namespace amrstream {

struct SliceJob {
  DatasetRequest dataset;
  FieldOptions field;
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
  float lineWidth = 1.5f;       // pixels
  bool lic = false;
  double licLength = 0.0;  // the LIC kernel's half-length, in the plane's coordinates; 0: 1/50
                           // of the window's width
  std::string out = "slice.png";
  std::string vti;  // the plane's samples (vector, channels, LIC) as VTK ImageData; empty: none
};

// The checks made before any work: the builtin dataset's size and the options' values.
void checkSliceJob(const SliceJob& job);

// Loads, builds the field, samples the plane, draws the figure and writes the files. Says the
// "input", "structure", "plane", "lines", "lic" and "output" lines; progress: stage "slicing",
// rows.
void runSliceJob(const SliceJob& job, const Reporter& reporter = {});

}  // namespace amrstream
