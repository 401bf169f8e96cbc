#include "formats/dataset_files.hpp"

#include <fstream>
#include <sstream>
#include <system_error>

#include "formats/enzo/enzo_reader.hpp"
#include "formats/load_input.hpp"

namespace amrstream::formats {

namespace {

namespace fs = std::filesystem;

// No ExaBricks config comes near this; a larger "config" is left to readExa to judge.
constexpr std::uintmax_t kMaxExaConfigBytes = std::uintmax_t(1) << 24;

// The config and the files its `cells` and `scalar` lines name, relative to it. Lines that make
// no sense are skipped: readExa reports them.
std::vector<fs::path> exaFiles(const fs::path& config) {
  std::vector<fs::path> files{config};
  std::error_code error;
  if (!fs::is_regular_file(config, error) || fs::file_size(config, error) > kMaxExaConfigBytes)
    return files;
  std::ifstream in(config);
  for (std::string line; std::getline(in, line);) {
    if (const auto hash = line.find('#'); hash != std::string::npos) line.resize(hash);
    std::istringstream words(line);
    std::string keyword, name, file;
    words >> keyword;
    if ((keyword == "cells" && words >> file) || (keyword == "scalar" && words >> name >> file))
      files.push_back(config.parent_path() / file);
  }
  return files;
}

// The input, its parameter file, PARAMETER.hierarchy, .harrays and every PARAMETER.cpuNNNN.
std::vector<fs::path> enzoFiles(const fs::path& input) {
  const fs::path parameter = enzoParameterFile(input);
  std::vector<fs::path> files{input, parameter, parameter.string() + ".hierarchy",
                              parameter.string() + ".harrays"};
  const std::string cpuPrefix = parameter.filename().string() + ".cpu";
  const fs::path directory = parameter.parent_path().empty() ? "." : parameter.parent_path();
  std::error_code error;
  for (const fs::directory_entry& entry : fs::directory_iterator(directory, error)) {
    const std::string name = entry.path().filename().string();
    if (name.size() > cpuPrefix.size() && name.starts_with(cpuPrefix) &&
        name.find_first_not_of("0123456789", cpuPrefix.size()) == std::string::npos)
      files.push_back(parameter.parent_path() / name);
  }
  return files;
}

}  // namespace

std::vector<fs::path> datasetFiles(const std::string& input) {
  switch (detectFormat(input)) {
    case Format::Builtin:
      return {};
    case Format::ExaBricks:
      return exaFiles(input);
    case Format::Enzo:
      return enzoFiles(input);
    case Format::Amrex:
    case Format::Flash:
    case Format::Gerris:
      break;
  }
  return {input};
}

}  // namespace amrstream::formats
