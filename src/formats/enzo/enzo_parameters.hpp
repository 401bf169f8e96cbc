#pragma once
// An Enzo parameter file (`DD0010/moving7_0010`): its `Key = value` lines, with typed reads that
// throw InputError naming the file and the key when a value is malformed.

#include <array>
#include <filesystem>
#include <map>
#include <optional>
#include <string>

namespace amrstream::formats {

class EnzoParameters {
 public:
  // Throws InputError when the path is not a readable regular file.
  explicit EnzoParameters(const std::filesystem::path& file);

  const std::filesystem::path& file() const { return file_; }
  const std::map<std::string, std::string>& values() const { return values_; }

  // Absent keys give nullopt; a value that is not exactly one finite number (or one per axis of
  // `axes`-dimensional data, parseAxisFinite) throws, naming the file, the key and the text.
  std::optional<double> number(const std::string& key) const;
  std::optional<std::array<double, 3>> threeNumbers(const std::string& key, int axes = 3) const;

 private:
  std::filesystem::path file_;
  std::map<std::string, std::string> values_;
};

}  // namespace amrstream::formats
