#include "amrstream/run_files.hpp"

#include <fmt/format.h>
#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <system_error>
#include <utility>

#include "amrstream/error.hpp"
#include "output/atomic_file.hpp"
#include "util/input_file.hpp"

namespace amrstream {

namespace fs = std::filesystem;

void removeTemporariesOnSignals() { output::removeTemporariesOnSignals(); }

void checkRegularFile(const fs::path& path) { regularFileSize(path); }

std::optional<RunFiles::Identity> RunFiles::identityOf(const fs::path& path, bool* directory) {
  struct stat status {};
  if (::stat(path.c_str(), &status) != 0) return std::nullopt;
  if (directory != nullptr) *directory = S_ISDIR(status.st_mode);
  return Identity{status.st_dev, status.st_ino};
}

RunFiles::File RunFiles::describe(std::string name, const fs::path& path) {
  File file{std::move(name), path, {}, std::nullopt, false};
  std::error_code error;
  file.canonical = fs::weakly_canonical(fs::absolute(path, error), error);
  if (error) file.canonical = fs::absolute(path, error).lexically_normal();
  file.identity = identityOf(path, &file.directory);
  return file;
}

void RunFiles::addInput(const fs::path& path) {
  File file = describe(path.string(), path);
  if (file.identity) inputs_.push_back(std::move(file));
}

void RunFiles::addInputs(const std::vector<fs::path>& paths) {
  for (const fs::path& path : paths) addInput(path);
}

void requireOutputExtension(const std::string& option, const fs::path& path,
                            const std::vector<std::string>& extensions, const std::string& format) {
  std::string extension = path.extension().string();
  for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (std::find(extensions.begin(), extensions.end(), extension) != extensions.end()) return;
  std::string names;
  for (const std::string& e : extensions) names += (names.empty() ? "" : " or ") + e;
  throw InputError(option, fmt::format("'{}': the file written is {}; name it {}", path.string(),
                                       format, names));
}

void RunFiles::addOutput(const std::string& option, const fs::path& path) {
  checkOutput(option, path);
  outputs_.push_back(describe(option, path));
}

void RunFiles::checkOutput(const std::string& option, const fs::path& path) const {
  const File output = describe(option, path);
  const std::string shown = path.string();
  if (output.directory) throw InputError(option, fmt::format("'{}' is a directory", shown));
  // Outputs are renamed over their target (AtomicFile): that would replace a device such as
  // /dev/null, or a FIFO, by a regular file.
  if (struct stat status{}; ::stat(path.c_str(), &status) == 0 && !S_ISREG(status.st_mode))
    throw InputError(option, fmt::format("'{}' exists and is not a regular file (a device, a FIFO "
                                         "or a socket); outputs replace their file whole",
                                         shown));
  const fs::path parent = output.canonical.parent_path();
  bool parentIsDirectory = false;
  if (!identityOf(parent, &parentIsDirectory) || !parentIsDirectory)
    throw InputError(option, fmt::format("cannot write '{}': the directory '{}' does not exist",
                                         shown, parent.string()));

  const auto same = [&](const File& other) {
    return (output.identity && output.identity == other.identity) ||
           output.canonical == other.canonical;
  };
  // The output's existing directories, from its own up to the root.
  std::vector<Identity> directories;
  for (fs::path p = parent;; p = p.parent_path()) {
    if (const std::optional<Identity> identity = identityOf(p, nullptr))
      directories.push_back(*identity);
    if (p == p.root_path() || p.empty()) break;
  }

  for (const File& input : inputs_) {
    if (same(input))
      throw InputError(option, fmt::format("'{}' is the input '{}': writing it would destroy the "
                                           "input; choose another name",
                                           shown, input.path.string()));
    for (const Identity& directory : directories)
      if (input.directory && directory == *input.identity)
        throw InputError(option, fmt::format("'{}' lies inside the input directory '{}'; write it "
                                             "elsewhere",
                                             shown, input.path.string()));
  }
  for (const File& other : outputs_)
    if (same(other))
      throw InputError(option, fmt::format("'{}' is also the output of {} ('{}'): one would "
                                           "replace the other; give each its own name",
                                           shown, other.name, other.path.string()));
}

}  // namespace amrstream
