#pragma once
// Checks of option values, run on the option's text before CLI11 converts it. A count is plain
// decimal digits within its bounds, and a real number finite and within its bounds (CLI11 alone
// takes "-1" as 2^64 - 1 for an unsigned option, "010" as octal 8, "1e99" or "inf" as infinity
// for a float, and "99999999999999999999" as the largest integer). An input file must be a
// regular file (a FIFO would block its reader, a device never end). A bad value fails the parse
// with CLI11's message "OPTION: PROBLEM".

#include <CLI/CLI.hpp>
#include <cstdint>
#include <limits>

namespace amrstream::cli {

inline constexpr double kFloatMax = std::numeric_limits<float>::max();
// The smallest positive values held without losing precision: anything smaller that is meant as
// positive would round towards 0.
inline constexpr double kFloatPositiveMin = std::numeric_limits<float>::min();
inline constexpr double kDoubleMax = std::numeric_limits<double>::max();
inline constexpr double kDoublePositiveMin = std::numeric_limits<double>::min();

// A whole number from `least` to `most`, in decimal digits alone without a leading zero.
CLI::Validator countIn(std::uint64_t least, std::uint64_t most);

// A finite number from `least` to `most`.
CLI::Validator numberIn(double least, double most);

// A finite number a float holds (for options stored as float).
CLI::Validator finiteFloat();
// A finite float > 0 (at least kFloatPositiveMin).
CLI::Validator positiveFloat();
// A finite float >= 0.
CLI::Validator nonNegativeFloat();
// The same for options stored as double.
CLI::Validator finiteDouble();
CLI::Validator positiveDouble();

// An existing regular file (symbolic links followed).
CLI::Validator regularFile();

}  // namespace amrstream::cli
