#pragma once
// The errors the library reports to its callers. Library code never exits.

#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace amrstream {

// Bad user input: a file, a dataset or a setting that cannot be used. The message names the
// source and says what is wrong. A setting is named neutrally (amrstream/settings.hpp: "step_size",
// and other settings in the problem as "{name}"); what() writes the names as they are, and front
// ends spell them their own way (spelled(cliFlag): "--step-size").
using SettingSpelling = std::function<std::string(std::string_view name)>;

// `{name}` references to settings in `text` (names of lowercase letters and underscores) spelled
// by `spell`; other braces are kept.
inline std::string spellSettings(std::string_view text, const SettingSpelling& spell) {
  std::string out;
  std::size_t at = 0;
  while (true) {
    const std::size_t open = text.find('{', at);
    const std::size_t close = open == std::string_view::npos ? open : text.find('}', open);
    if (close == std::string_view::npos) break;
    const std::string_view name = text.substr(open + 1, close - open - 1);
    const bool isName =
        !name.empty() && name.find_first_not_of("abcdefghijklmnopqrstuvwxyz_") == name.npos;
    out.append(text.substr(at, open - at));
    if (isName)
      out += spell(name);
    else
      out.append(text.substr(open, close - open + 1));
    at = close + 1;
  }
  out.append(text.substr(at));
  return out;
}

// The neutral spelling: the names as they are (what Python's keywords are).
inline std::string plainName(std::string_view name) { return std::string(name); }

// The command line's spelling: --step-size for step_size.
inline std::string cliFlag(std::string_view name) {
  std::string flag = "--" + std::string(name);
  for (char& c : flag)
    if (c == '_') c = '-';
  return flag;
}

class InputError : public std::runtime_error {
 public:
  // `source` names a file or a dataset (a path, builtin:NAME), or what the caller called it.
  InputError(const std::string& source, const std::string& problem)
      : std::runtime_error(spellSettings(source + ": " + problem, plainName)),
        source_(source),
        problem_(problem) {}

  // A setting's value is at fault.
  static InputError aboutSetting(std::string_view setting, const std::string& problem) {
    InputError error(std::string(setting), problem);
    error.setting_ = true;
    return error;
  }

  // The input file `path` cannot be opened: the system's error `code` (errno), which Python
  // raises as its OSError subclass (ENOENT: FileNotFoundError, EACCES: PermissionError).
  static InputError fileError(const std::string& path, int code, const std::string& problem) {
    InputError error(path, problem);
    error.systemError_ = code;
    return error;
  }

  // The message with settings spelled by `spell`: a setting's name before the problem, and the
  // names the source and the problem mention as {name}.
  std::string spelled(const SettingSpelling& spell) const {
    const std::string source = setting_ ? spell(source_) : spellSettings(source_, spell);
    return source + ": " + spellSettings(problem_, spell);
  }

  const std::string& source() const { return source_; }  // the setting's name for a setting
  const std::string& problem() const { return problem_; }
  bool isAboutSetting() const { return setting_; }
  int systemError() const { return systemError_; }  // 0: not a system error

 private:
  std::string source_, problem_;
  bool setting_ = false;
  int systemError_ = 0;
};

// The error for a setting, as InputError::aboutSetting makes it.
inline InputError settingError(std::string_view setting, const std::string& problem) {
  return InputError::aboutSetting(setting, problem);
}

// What every rank of an MPI job throws when some rank's phase failed: the lowest failing rank's
// error, named with that rank ("rank 1 of 3: ...") unless every rank failed, and its exit code (2
// for bad input, else 1). A bad setting there stays an InputError to spell (`cause`).
class RankFailure : public std::runtime_error {
 public:
  RankFailure(const std::string& message, int exitCode,
              std::optional<InputError> cause = std::nullopt, std::string rank = {})
      : std::runtime_error(message),
        exitCode_(exitCode),
        cause_(std::move(cause)),
        rank_(std::move(rank)) {}
  int exitCode() const { return exitCode_; }
  const std::optional<InputError>& cause() const { return cause_; }
  const std::string& rank() const { return rank_; }  // "rank 1 of 3: ", or empty

 private:
  int exitCode_;
  std::optional<InputError> cause_;
  std::string rank_;
};

}  // namespace amrstream
