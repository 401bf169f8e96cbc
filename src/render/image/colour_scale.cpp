#include "render/image/colour_scale.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace amrstream::render {
namespace {

struct Named {
  ScaleKind kind;
  std::string_view name;
};
constexpr Named kNames[] = {
    {ScaleKind::Linear, "linear"}, {ScaleKind::Log, "log"}, {ScaleKind::SymLog, "symlog"}};

double symmetricLog(double value, double width) {
  const double magnitude = std::abs(value);
  const double t = magnitude <= width ? magnitude / width : 1.0 + std::log10(magnitude / width);
  return std::copysign(t, value);
}

std::string tickLabel(double value) {
  if (value == 0.0) return "0";
  return fmt::format("{:g}", value);
}

// The multiple of 1, 2 or 5 times a power of ten that cuts `span` into at most `most` - 1 steps.
double niceStep(double span, int most) {
  const double rough = span / std::max(1, most - 1);
  const double decade = std::pow(10.0, std::floor(std::log10(rough)));
  for (const double factor : {1.0, 2.0, 5.0, 10.0})
    if (factor * decade >= rough * (1.0 - 1e-9)) return factor * decade;
  return 10.0 * decade;
}

// The round values k * step inside [lower, upper].
std::vector<double> multiplesInside(double lower, double upper, double step) {
  std::vector<double> values;
  const double first = std::ceil(lower / step - 1e-9);
  for (double k = first; k * step <= upper + step * 1e-9; ++k) {
    const double v = std::abs(k) < 0.5 ? 0.0 : k * step;
    values.push_back(v);
  }
  return values;
}

// The next round step below `step` (1, 2, 5 x 10^k).
double smallerNiceStep(double step) {
  const double decade = std::pow(10.0, std::floor(std::log10(step) + 1e-9));
  const double factor = step / decade;
  return factor > 5.5   ? 5.0 * decade
         : factor > 2.5 ? 2.0 * decade
         : factor > 1.5 ? decade
                        : 0.5 * decade;
}

// Round values evenly spaced in the value itself, inside [lower, upper]: at least two (a
// smaller step than `most` asks for where the range falls between round values).
std::vector<double> linearTickValues(double lower, double upper, int most) {
  double step = niceStep(upper - lower, most);
  std::vector<double> values = multiplesInside(lower, upper, step);
  while (values.size() < 2 && step > (upper - lower) * 1e-6) {
    step = smallerNiceStep(step);
    values = multiplesInside(lower, upper, step);
  }
  return values;
}

// Powers of ten inside [lower, upper] (both > 0), every k-th decade so that at most `most` show.
std::vector<double> decadeTickValues(double lower, double upper, int most) {
  const int first = static_cast<int>(std::ceil(std::log10(lower) - 1e-9));
  const int last = static_cast<int>(std::floor(std::log10(upper) + 1e-9));
  const int decades = last - first + 1;
  const int every = std::max(1, (decades + most - 1) / most);
  std::vector<double> values;
  for (int e = first; e <= last; e += every) values.push_back(std::pow(10.0, e));
  return values;
}

}  // namespace

std::optional<ScaleKind> parseScaleKind(std::string_view name) {
  for (const Named& named : kNames)
    if (named.name == name) return named.kind;
  return std::nullopt;
}

std::string_view scaleKindName(ScaleKind kind) {
  for (const Named& named : kNames)
    if (named.kind == kind) return named.name;
  throw std::logic_error("unknown ScaleKind");
}

double ColourScale::coordinate(double value) const {
  switch (kind) {
    case ScaleKind::Linear:
      return value;
    case ScaleKind::Log:
      return std::log10(value > 0.0 ? std::max(value, min) : min);
    case ScaleKind::SymLog:
      return symmetricLog(value, linearWidth);
  }
  throw std::logic_error("unknown ScaleKind");
}

double ColourScale::position(double value) const {
  if (std::isnan(value)) return value;
  const double low = coordinate(min), high = coordinate(max);
  return std::clamp((coordinate(value) - low) / (high - low), 0.0, 1.0);
}

double ColourScale::valueAt(double t) const {
  const double low = coordinate(min), high = coordinate(max);
  const double c = low + t * (high - low);
  switch (kind) {
    case ScaleKind::Linear:
      return c;
    case ScaleKind::Log:
      return std::pow(10.0, c);
    case ScaleKind::SymLog: {
      const double magnitude = std::abs(c);
      const double v = magnitude <= 1.0 ? magnitude * linearWidth
                                        : linearWidth * std::pow(10.0, magnitude - 1.0);
      return std::copysign(v, c);
    }
  }
  throw std::logic_error("unknown ScaleKind");
}

void checkScale(const ColourScale& s) {
  if (!std::isfinite(s.min) || !std::isfinite(s.max))
    throw std::invalid_argument(fmt::format("the range {} to {} is not finite", s.min, s.max));
  if (!(s.min < s.max))
    throw std::invalid_argument(
        fmt::format("the range's minimum {} is not below its maximum {}", s.min, s.max));
  if (s.kind == ScaleKind::Log && !(s.min > 0.0))
    throw std::invalid_argument(fmt::format(
        "a log scale needs a positive minimum, not {}; use symlog for data of both signs", s.min));
  if (s.kind == ScaleKind::SymLog && !(s.linearWidth > 0.0 && std::isfinite(s.linearWidth)))
    throw std::invalid_argument(
        fmt::format("symlog's linear width must be positive, not {}", s.linearWidth));
}

double defaultLinearWidth(double min, double max) {
  const double largest = std::max(std::abs(min), std::abs(max));
  return largest > 0.0 ? largest * 1e-3 : 1.0;
}

std::vector<ScaleTick> scaleTicks(const ColourScale& s, int most) {
  checkScale(s);
  most = std::max(2, most);
  std::vector<double> values;
  if (s.kind == ScaleKind::Linear || (s.kind == ScaleKind::Log && s.max / s.min < 100.0)) {
    values = linearTickValues(s.min, s.max, most);
  } else if (s.kind == ScaleKind::Log) {
    values = decadeTickValues(s.min, s.max, most);
  } else {
    // The decades beyond the linear part on each side, and 0 when the range holds it.
    const int sideMost = std::max(1, (most - 1) / 2);
    const double w = s.linearWidth;
    if (s.min < -w) {
      std::vector<double> magnitudes = decadeTickValues(std::max(w, -s.max), -s.min, sideMost);
      for (auto m = magnitudes.rbegin(); m != magnitudes.rend(); ++m) values.push_back(-*m);
    }
    if (s.min <= 0.0 && s.max >= 0.0) values.push_back(0.0);
    if (s.max > w) {
      const std::vector<double> positive = decadeTickValues(std::max(w, s.min), s.max, sideMost);
      values.insert(values.end(), positive.begin(), positive.end());
    }
    if (values.size() < 2) values = linearTickValues(s.min, s.max, most);
  }
  std::vector<ScaleTick> ticks;
  for (const double v : values)
    if (v >= s.min - 1e-12 * std::abs(s.min) && v <= s.max + 1e-12 * std::abs(s.max))
      ticks.push_back({v, s.position(v), tickLabel(v)});
  return ticks;
}

}  // namespace amrstream::render
