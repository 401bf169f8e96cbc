#pragma once
// How a scalar maps to a place along a colour map, and the ticks a colour bar shows for it.
//
// Linear: t = (v - min) / (max - min). Log: the same in log10 v; min must be positive, and values
// at or below 0 take the lower end. Symmetric log ("symlog"): linear within +-linearWidth of 0
// and logarithmic outside, each decade beyond linearWidth as long as the linear part on one side
// (matplotlib's SymLogNorm with base 10 and linscale 1), so data of both signs spanning many
// decades keep their sign and their orders of magnitude.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace amrstream::render {

enum class ScaleKind { Linear, Log, SymLog };

// "linear", "log", "symlog"; nullopt for anything else.
std::optional<ScaleKind> parseScaleKind(std::string_view name);
std::string_view scaleKindName(ScaleKind kind);

struct ColourScale {
  ScaleKind kind = ScaleKind::Linear;
  double min = 0.0, max = 1.0;  // the values at t = 0 and t = 1
  double linearWidth = 1.0;     // SymLog: the half-width of the linear part, > 0

  // The scale's coordinate of a value: v, log10 v, or the symmetric log; monotonic, so positions
  // along the map are affine in it. Values a log scale cannot take give the lower end's.
  double coordinate(double value) const;
  // t in [0, 1] (clamped) for a value; NaN stays NaN.
  double position(double value) const;
  // The value at t (the inverse of position inside [0, 1]).
  double valueAt(double position) const;
};

// Throws std::invalid_argument saying what is wrong: a bound that is not finite, min >= max, a
// log scale with min <= 0, or a symlog scale whose linearWidth is not positive and finite.
void checkScale(const ColourScale& scale);

// A positive default linear width for symlog over [min, max]: a thousandth of the largest
// magnitude, so three decades show on each side.
double defaultLinearWidth(double min, double max);

struct ScaleTick {
  double value;
  double position;  // t in [0, 1]
  std::string label;
};

// At most `most` (>= 2) ticks inside [min, max], in increasing order, at round values: multiples
// of 1, 2 or 5 times a power of ten (linear, and log scales spanning less than two decades),
// powers of ten (log; every k-th decade when there are too many), or 0 and +-powers of ten
// (symlog). Labels are as short as "%g" makes them.
std::vector<ScaleTick> scaleTicks(const ColourScale& scale, int most);

}  // namespace amrstream::render
