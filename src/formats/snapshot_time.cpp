#include "formats/snapshot_time.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <glob.h>

#include <algorithm>
#include <filesystem>
#include <set>
#include <string_view>

#include "amrstream/error.hpp"
#include "formats/amrex/amrex_reader.hpp"
#include "formats/enzo/enzo_info.hpp"
#include "formats/enzo/enzo_parameters.hpp"
#include "formats/enzo/enzo_reader.hpp"
#include "formats/exa/exa_format.hpp"
#include "formats/flash/flash_file.hpp"
#include "formats/flash/flash_info.hpp"
#include "formats/gerris/gerris_reader.hpp"
#include "formats/load_input.hpp"
#include "synth/generators.hpp"

namespace amrstream::formats {

namespace {

namespace fs = std::filesystem;
constexpr std::string_view kBuiltinPrefix = "builtin:";

// loadInput(input, {}) generates builtin datasets at time 0; an unknown kind fails as it does.
double builtinTime(const std::string& input) {
  const std::string kind = input.substr(kBuiltinPrefix.size());
  const std::vector<std::string> kinds = synth::generatorKinds();
  if (std::ranges::find(kinds, kind) == kinds.end())
    throw InputError(input, fmt::format("unknown generator kind '{}' (kinds: {})", kind,
                                        fmt::join(kinds, ", ")));
  return 0.0;
}

// Without its parameter file an Enzo dataset states no time, as readEnzo finds; a parameter file
// that is not a regular file (a FIFO) is refused by name, as readEnzo refuses it.
std::optional<double> enzoTime(const std::string& input) {
  const fs::path parameterFile = enzoParameterFile(input);
  std::error_code error;
  if (!fs::exists(parameterFile, error) || fs::is_directory(parameterFile, error))
    return std::nullopt;
  return readEnzoTime(EnzoParameters(parameterFile));
}

// Frees a glob_t's matches when it goes out of scope.
class GlobMatches {
 public:
  explicit GlobMatches(const std::string& pattern) {
    result_ = glob(pattern.c_str(), 0, nullptr, &matches_);
  }
  GlobMatches(const GlobMatches&) = delete;
  GlobMatches& operator=(const GlobMatches&) = delete;
  ~GlobMatches() { globfree(&matches_); }

  int result() const { return result_; }
  std::span<char* const> paths() const { return {matches_.gl_pathv, matches_.gl_pathc}; }

 private:
  glob_t matches_{};
  int result_ = 0;
};

std::vector<std::string> globMatches(const std::string& pattern) {
  const GlobMatches matches(pattern);
  if (matches.result() == GLOB_NOMATCH) throw InputError(pattern, "matches no file");
  if (matches.result() != 0)
    throw InputError(pattern, "cannot expand the pattern (out of memory or a read error)");
  return {matches.paths().begin(), matches.paths().end()};
}

bool keptAsGiven(const std::string& argument) {
  std::error_code error;
  return argument.starts_with(kBuiltinPrefix) || fs::exists(argument, error);
}

// One key per path however it is spelt: `dir/./a`, `dir//a` and `dir/a/` name `dir/a`.
std::string pathKey(const std::string& path) {
  if (path.starts_with(kBuiltinPrefix)) return path;
  std::error_code error;
  fs::path key = fs::absolute(path, error).lexically_normal();
  if (!key.has_filename() && key.has_parent_path()) key = key.parent_path();
  return key.string();
}

}  // namespace

std::optional<double> snapshotTime(const std::string& input) {
  switch (detectFormat(input)) {
    case Format::Builtin:
      return builtinTime(input);
    case Format::ExaBricks:
      return readExaTime(input);
    case Format::Amrex:
      return amrexPlotfileTime(input);
    case Format::Enzo:
      return enzoTime(input);
    case Format::Flash:
      return flash::readFlashTime(flash::FlashFile(input));
    case Format::Gerris:
      return readGerrisTime(input);
  }
  throw InputError(input, "unknown input format");
}

std::string snapshotDataset(const std::string& path) {
  const fs::path file(path);
  const std::string name = file.filename().string();
  const std::size_t dot = name.find('.');
  if (dot == std::string::npos || dot == 0) return path;
  const fs::path stem = file.parent_path() / name.substr(0, dot);
  std::error_code error;
  if (!fs::is_regular_file(stem, error)) return path;
  try {
    return detectFormat(stem.string()) == Format::Enzo ? stem.string() : path;
  } catch (const InputError&) {
    return path;  // the stem is no dataset: `path` stands for itself
  }
}

std::vector<std::string> expandSnapshotPatterns(std::span<const std::string> patterns) {
  std::vector<std::string> paths;
  std::set<std::string> seen;
  const auto add = [&](const std::string& path) {
    if (seen.insert(pathKey(path)).second) paths.push_back(path);
  };
  for (const std::string& pattern : patterns) {
    if (keptAsGiven(pattern)) {
      add(pattern);
      continue;
    }
    for (const std::string& match : globMatches(pattern)) add(match);
  }
  return paths;
}

}  // namespace amrstream::formats
