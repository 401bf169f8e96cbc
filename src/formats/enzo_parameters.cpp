#include "enzo_parameters.hpp"

#include <fmt/format.h>

#include <fstream>
#include <sstream>

#include "util/input_error.hpp"

namespace amrstream::formats {

namespace {

std::string trim(std::string s) {
  const auto* ws = " \t\r\n";
  s.erase(0, s.find_first_not_of(ws));
  s.erase(s.find_last_not_of(ws) + 1);
  return s;
}

}  // namespace

EnzoParameters::EnzoParameters(const std::filesystem::path& file) : file_(file) {
  std::ifstream in(file);
  if (!in) throw InputError(file.string(), "cannot open the parameter file");
  for (std::string line; std::getline(in, line);) {
    const auto eq = line.find('=');
    if (eq != std::string::npos) values_[trim(line.substr(0, eq))] = trim(line.substr(eq + 1));
  }
}

std::optional<double> EnzoParameters::number(const std::string& key) const {
  const auto it = values_.find(key);
  if (it == values_.end()) return std::nullopt;
  std::istringstream in(it->second);
  double value = 0.0;
  std::string extra;
  if (!(in >> value) || (in >> extra))
    throw InputError(file_.string(), fmt::format("{} is not a number: '{}'", key, it->second));
  return value;
}

std::optional<std::array<double, 3>> EnzoParameters::threeNumbers(const std::string& key) const {
  const auto it = values_.find(key);
  if (it == values_.end()) return std::nullopt;
  std::istringstream in(it->second);
  std::array<double, 3> values{};
  std::string extra;
  if (!(in >> values[0] >> values[1] >> values[2]) || (in >> extra))
    throw InputError(file_.string(),
                     fmt::format("{} needs 3 numbers, got '{}'", key, it->second));
  return values;
}

}  // namespace amrstream::formats
