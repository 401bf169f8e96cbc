#include "option_checks.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <string>
#include <system_error>

#include "amrstream/error.hpp"
#include "amrstream/run_files.hpp"

namespace amrstream::cli {

namespace {

// The text as a double when from_chars takes all of it (no sign '+', spaces or hex), else
// nothing. Beyond double's range: infinite on overflow, 0 or a denormal on underflow.
std::optional<double> parsedReal(const std::string& text) {
  double value = 0.0;
  const auto [end, error] =
      std::from_chars(text.data(), text.data() + text.size(), value, std::chars_format::general);
  if (text.empty() || end != text.data() + text.size()) return std::nullopt;
  if (error == std::errc::result_out_of_range) return std::strtod(text.c_str(), nullptr);
  if (error != std::errc()) return std::nullopt;
  return value;
}

// `requirement` ("> 0") names the bounds in messages and in the help; empty: "least..most".
CLI::Validator realValidator(double least, double most, const std::string& requirement) {
  return CLI::Validator(
      [least, most, requirement](std::string& text) -> std::string {
        const std::optional<double> value = parsedReal(text);
        if (!value) return fmt::format("'{}' is not a number", text);
        if (!std::isfinite(*value)) return fmt::format("'{}' is not a finite number", text);
        if (*value >= least && *value <= most) return {};
        if (requirement.empty())
          return fmt::format("{} is outside the range {:g} to {:g}", text, least, most);
        return fmt::format("{} is not {} (from {:g} to {:g})", text, requirement, least, most);
      },
      requirement.empty() ? fmt::format("{:g}..{:g}", least, most) : requirement);
}

}  // namespace

CLI::Validator countIn(std::uint64_t least, std::uint64_t most) {
  return CLI::Validator(
      [least, most](std::string& text) -> std::string {
        const auto outside = [&] {
          return fmt::format("{} is outside the range {} to {}", text, least, most);
        };
        if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos)
          return fmt::format("'{}' is not a whole number from {} to {}", text, least, most);
        // CLI11 would read a leading 0 as octal.
        if (text.size() > 1 && text.front() == '0')
          return fmt::format("'{}' has a leading zero; write the number in decimal without it",
                             text);
        std::uint64_t value = 0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (error == std::errc::result_out_of_range) return outside();
        if (value < least || value > most) return outside();
        return {};
      },
      fmt::format("{}..{}", least, most));
}

CLI::Validator numberIn(double least, double most) { return realValidator(least, most, ""); }

CLI::Validator finiteFloat() {
  return realValidator(-kFloatMax, kFloatMax, "finite in float's range");
}

CLI::Validator positiveFloat() { return realValidator(kFloatPositiveMin, kFloatMax, "> 0"); }

CLI::Validator nonNegativeFloat() { return realValidator(0.0, kFloatMax, ">= 0"); }

CLI::Validator finiteDouble() { return realValidator(-kDoubleMax, kDoubleMax, "finite"); }

CLI::Validator positiveDouble() { return realValidator(kDoublePositiveMin, kDoubleMax, "> 0"); }

CLI::Validator regularFile() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        try {
          checkRegularFile(text);
        } catch (const InputError& error) {
          return error.what();
        }
        return {};
      },
      "FILE");
}

}  // namespace amrstream::cli
