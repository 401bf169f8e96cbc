#pragma once
// Command-line options made from the library's settings (amrstream/settings.hpp): the flag is the
// setting's name with dashes, the help its text with other settings spelled as flags, the default
// shown is the setting's, and the value is checked against its range or choices.

#include <CLI/CLI.hpp>
#include <cstdint>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "amrstream/settings.hpp"
#include "option_checks.hpp"

namespace amrstream::cli {

// The setting's help text for the command line.
std::string settingHelp(const Setting& setting);

// The check of a value of type T against the setting's range or choices; none where it has
// neither.
template <typename T>
std::optional<CLI::Validator> settingCheck(const Setting& s) {
  if constexpr (std::is_same_v<T, bool>) {
    return std::nullopt;
  } else if constexpr (std::is_integral_v<T>) {
    // double(max) of a 64-bit type rounds up past max, so compare before converting.
    const auto typeMost = std::uint64_t(std::numeric_limits<T>::max());
    const std::uint64_t most = s.most >= double(typeMost) ? typeMost : std::uint64_t(s.most);
    return countIn(std::uint64_t(std::max(0.0, s.least)), most);
  } else if constexpr (std::is_floating_point_v<T>) {
    constexpr bool single = std::is_same_v<T, float>;
    const double limit = double(std::numeric_limits<T>::max());
    const double least = std::max(s.least, -limit), most = std::min(s.most, limit);
    if (s.positive) return single ? positiveFloat() : positiveDouble();
    if (least == -kFloatMax && most == kFloatMax) return finiteFloat();
    if (least == -limit && most == limit) return single ? finiteFloat() : finiteDouble();
    if (single && least == 0.0 && most == limit) return nonNegativeFloat();
    return numberIn(least, most);
  } else {
    if (s.choices.empty()) return std::nullopt;
    std::vector<std::string> choices;
    for (std::size_t at = 0; at <= s.choices.size();) {
      const std::size_t bar = std::min(s.choices.find('|', at), s.choices.size());
      choices.emplace_back(s.choices.substr(at, bar - at));
      at = bar + 1;
    }
    return CLI::IsMember(choices);
  }
}

template <typename T>
struct OptionValue {
  using type = T;
};
template <typename T>
struct OptionValue<std::optional<T>> {
  using type = T;
};
template <typename T>
struct OptionValue<std::vector<T>> {
  using type = T;
};

// --NAME bound to `target` (a number, text, optional or list of them); a flag for bool targets.
template <typename T>
CLI::Option* addSetting(CLI::App& command, const Setting& setting, T& target) {
  const std::string flag = cliFlag(setting.name);
  if constexpr (std::is_same_v<T, bool>) {
    return command.add_flag(flag, target, settingHelp(setting));
  } else {
    CLI::Option* option = command.add_option(flag, target, settingHelp(setting));
    if (const std::string shown = shownDefault(setting); !shown.empty()) option->default_str(shown);
    if (auto check = settingCheck<typename OptionValue<T>::type>(setting)) option->check(*check);
    return option;
  }
}

}  // namespace amrstream::cli
