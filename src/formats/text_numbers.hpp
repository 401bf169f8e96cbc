#pragma once
// Numbers in the readers' text files, parsed whole or refused by name: every error names where
// the text came from (file and line or key), what it should be, and the text itself.

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace amrstream::formats {

// `text` for an error message: its first 60 bytes, other bytes than printable ASCII as \xNN.
std::string excerpt(std::string_view text);

// `text` without the blanks (spaces, tabs, CR, LF) around it.
std::string_view trimmed(std::string_view text);

// Blank-separated words of `text` (spaces, tabs, CR, LF).
std::vector<std::string_view> splitWords(std::string_view text);

// `text` (blanks around it allowed) as an integer in [low, high]; throws InputError(where,
// "WHAT is not an integer in [low, high]: 'TEXT'") otherwise.
std::int64_t parseInteger(std::string_view text, const std::string& where, const std::string& what,
                          std::int64_t low, std::int64_t high);

// `text` as a finite number; throws InputError(where, "WHAT is not a finite number: 'TEXT'").
double parseFinite(std::string_view text, const std::string& where, const std::string& what);

// Exactly three integers in [low, high], or three finite numbers.
std::array<std::int64_t, 3> parseThreeIntegers(std::string_view text, const std::string& where,
                                               const std::string& what, std::int64_t low,
                                               std::int64_t high);
std::array<double, 3> parseThreeFinite(std::string_view text, const std::string& where,
                                       const std::string& what);

// One value per axis of `axes`-dimensional data (2 or 3). With 2 axes a third value may follow
// (some writers pad to three); it is checked as the others and replaced by `z`, as it is when
// absent.
std::array<std::int64_t, 3> parseAxisIntegers(std::string_view text, const std::string& where,
                                              const std::string& what, std::int64_t low,
                                              std::int64_t high, int axes, std::int64_t z);
std::array<double, 3> parseAxisFinite(std::string_view text, const std::string& where,
                                      const std::string& what, int axes, double z);

}  // namespace amrstream::formats
