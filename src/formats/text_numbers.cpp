#include "formats/text_numbers.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>

#include "amrstream/error.hpp"

namespace amrstream::formats {

namespace {

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

// from_chars refuses the leading '+' that text files may write.
std::string_view withoutPlus(std::string_view word) {
  if (word.size() > 1 && word.front() == '+' && word[1] != '-') word.remove_prefix(1);
  return word;
}

}  // namespace

std::string_view trimmed(std::string_view text) {
  while (!text.empty() && isBlank(text.front())) text.remove_prefix(1);
  while (!text.empty() && isBlank(text.back())) text.remove_suffix(1);
  return text;
}

std::string excerpt(std::string_view text) {
  constexpr std::size_t kShown = 60;
  std::string shown;
  for (const char c : text.substr(0, kShown)) {
    const auto byte = static_cast<unsigned char>(c);
    shown += byte >= 0x20 && byte < 0x7f ? std::string(1, c) : fmt::format("\\x{:02x}", byte);
  }
  return text.size() <= kShown ? shown : shown + "...";
}

std::vector<std::string_view> splitWords(std::string_view text) {
  std::vector<std::string_view> words;
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && isBlank(text[i])) ++i;
    const std::size_t start = i;
    while (i < text.size() && !isBlank(text[i])) ++i;
    if (i > start) words.push_back(text.substr(start, i - start));
  }
  return words;
}

std::int64_t parseInteger(std::string_view text, const std::string& where, const std::string& what,
                          std::int64_t low, std::int64_t high) {
  const std::string_view word = withoutPlus(trimmed(text));
  std::int64_t value = 0;
  const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
  if (word.empty() || error != std::errc() || end != word.data() + word.size() || value < low ||
      value > high)
    throw InputError(where, fmt::format("{} is not an integer in [{}, {}]: '{}'", what, low, high,
                                        excerpt(text)));
  return value;
}

double parseFinite(std::string_view text, const std::string& where, const std::string& what) {
  const std::string_view word = withoutPlus(trimmed(text));
  double value = 0.0;
  const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
  if (word.empty() || error != std::errc() || end != word.data() + word.size() ||
      !std::isfinite(value))
    throw InputError(where, fmt::format("{} is not a finite number: '{}'", what, excerpt(text)));
  return value;
}

namespace {

std::vector<std::string_view> axisWords(std::string_view text, const std::string& where,
                                        const std::string& what, int axes, const char* kind) {
  std::vector<std::string_view> words = splitWords(text);
  const bool fits = words.size() == 3 || (axes == 2 && words.size() == 2);
  if (!fits)
    throw InputError(where, fmt::format("{} needs {} {}, got '{}'", what,
                                        axes == 2 ? "2 (or 3)" : "3", kind, excerpt(text)));
  return words;
}

}  // namespace

std::array<std::int64_t, 3> parseAxisIntegers(std::string_view text, const std::string& where,
                                              const std::string& what, std::int64_t low,
                                              std::int64_t high, int axes, std::int64_t z) {
  const std::vector<std::string_view> words = axisWords(text, where, what, axes, "integers");
  std::array<std::int64_t, 3> values{0, 0, z};
  for (std::size_t a = 0; a < words.size(); ++a) {
    const std::int64_t value = parseInteger(words[a], where, what, low, high);
    if (int(a) < axes) values[a] = value;
  }
  return values;
}

std::array<double, 3> parseAxisFinite(std::string_view text, const std::string& where,
                                      const std::string& what, int axes, double z) {
  const std::vector<std::string_view> words = axisWords(text, where, what, axes, "numbers");
  std::array<double, 3> values{0.0, 0.0, z};
  for (std::size_t a = 0; a < words.size(); ++a) {
    const double value = parseFinite(words[a], where, what);
    if (int(a) < axes) values[a] = value;
  }
  return values;
}

std::array<std::int64_t, 3> parseThreeIntegers(std::string_view text, const std::string& where,
                                               const std::string& what, std::int64_t low,
                                               std::int64_t high) {
  return parseAxisIntegers(text, where, what, low, high, 3, 0);
}

std::array<double, 3> parseThreeFinite(std::string_view text, const std::string& where,
                                       const std::string& what) {
  return parseAxisFinite(text, where, what, 3, 0.0);
}

}  // namespace amrstream::formats
