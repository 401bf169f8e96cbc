#pragma once
// "Did you mean" for a name that is not there: the candidate the given name most likely meant,
// ignoring case, or within a few typing mistakes of it.

#include <algorithm>
#include <cctype>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace amrstream {

namespace detail {

inline char folded(char c) { return char(std::tolower(static_cast<unsigned char>(c))); }

// Levenshtein distance of a and b, ignoring case.
inline std::size_t editDistance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      const bool same = folded(a[i - 1]) == folded(b[j - 1]);
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (same ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

}  // namespace detail

// The candidate `given` most likely meant: the closest by edit distance, ignoring case, when it
// is at most a third of the name's length away (at least 1, at most 3); nothing otherwise.
template <typename Names>
std::optional<std::string> closestName(std::string_view given, const Names& candidates) {
  const std::size_t allowed = std::clamp<std::size_t>(given.size() / 3, 1, 3);
  std::optional<std::string> best;
  std::size_t bestDistance = allowed + 1;
  for (const auto& candidate : candidates) {
    const std::size_t d = detail::editDistance(given, candidate);
    if (d < bestDistance) {
      bestDistance = d;
      best = std::string(candidate);
    }
  }
  return best;
}

// " (did you mean 'NAME'?)" for the closest candidate, or "" when none is close.
template <typename Names>
std::string didYouMean(std::string_view given, const Names& candidates) {
  const std::optional<std::string> name = closestName(given, candidates);
  return name ? " (did you mean '" + *name + "'?)" : "";
}

}  // namespace amrstream
