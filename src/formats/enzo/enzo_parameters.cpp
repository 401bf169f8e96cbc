#include "formats/enzo/enzo_parameters.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>

#include "amrstream/error.hpp"
#include "formats/input_bytes.hpp"
#include "formats/text_numbers.hpp"

namespace amrstream::formats {

EnzoParameters::EnzoParameters(const std::filesystem::path& file) : file_(file) {
  const std::string text = readWholeFile(file, "the parameter file");
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    const std::string_view line(text.data() + start, end - start);
    const auto eq = line.find('=');
    if (eq != std::string_view::npos)
      values_[std::string(trimmed(line.substr(0, eq)))] = std::string(trimmed(line.substr(eq + 1)));
    start = end + 1;
  }
}

std::optional<double> EnzoParameters::number(const std::string& key) const {
  const auto it = values_.find(key);
  if (it == values_.end()) return std::nullopt;
  const std::string_view text = it->second;
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc() || end != text.data() + text.size() ||
      !std::isfinite(value))
    throw InputError(file_.string(), fmt::format("{} is not a number: '{}'", key, excerpt(text)));
  return value;
}

std::optional<std::array<double, 3>> EnzoParameters::threeNumbers(const std::string& key,
                                                                  int axes) const {
  const auto it = values_.find(key);
  if (it == values_.end()) return std::nullopt;
  return parseAxisFinite(it->second, file_.string(), key, axes, 0.0);
}

}  // namespace amrstream::formats
