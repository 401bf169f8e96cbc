#include "load_input.hpp"

#include <array>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "amrex_reader.hpp"
#include "enzo_reader.hpp"
#include "exa_format.hpp"
#include "flash_reader.hpp"
#include "gerris_reader.hpp"
#include "util/input_error.hpp"

namespace amrstream::formats {

namespace {

namespace fs = std::filesystem;
constexpr std::string_view kBuiltinPrefix = "builtin:";

std::string firstBytes(const fs::path& path, std::size_t n) {
  std::ifstream in(path, std::ios::binary);
  std::string bytes(n, '\0');
  in.read(bytes.data(), std::streamsize(n));
  bytes.resize(std::size_t(in.gcount()));
  return bytes;
}

bool isHdf5(const fs::path& path) { return firstBytes(path, 8) == "\x89HDF\r\n\x1a\n"; }

// Enzo writes PREFIX (parameters), PREFIX.hierarchy, PREFIX.harrays and PREFIX.cpuNNNN.
bool isEnzo(const fs::path& path) {
  const std::string ext = path.extension().string();
  if (ext == ".hierarchy" || ext == ".harrays" || ext.starts_with(".cpu")) return true;
  return fs::exists(path.string() + ".hierarchy");
}

}  // namespace

std::string_view formatName(Format format) {
  switch (format) {
    case Format::Builtin:
      return "builtin";
    case Format::ExaBricks:
      return "ExaBricks";
    case Format::Amrex:
      return "AMReX plotfile";
    case Format::Enzo:
      return "Enzo";
    case Format::Flash:
      return "FLASH";
    case Format::Gerris:
      return "Gerris";
  }
  return "unknown";
}

Format detectFormat(const std::string& input) {
  if (input.starts_with(kBuiltinPrefix)) return Format::Builtin;
  const fs::path path(input);
  if (!fs::exists(path)) throw InputError(input, "no such file");
  if (fs::is_directory(path)) {
    if (firstBytes(path / "Header", 9) == "HyperCLaw") return Format::Amrex;
    throw InputError(input,
                     "a directory, but not an AMReX plotfile (no Header starting with "
                     "HyperCLaw)");
  }
  if (path.extension() == ".exa") return Format::ExaBricks;
  if (isEnzo(path)) return Format::Enzo;
  if (isHdf5(path)) return Format::Flash;
  if (firstBytes(path, 4) == "# 1:") return Format::Gerris;
  throw InputError(input,
                   "unknown input format (expected builtin:NAME, an ExaBricks .exa "
                   "config, an AMReX plotfile directory, an Enzo dataset, a FLASH HDF5 "
                   "file or a Gerris text dump)");
}

bricks::AmrField loadInput(const std::string& input,
                           const synth::GeneratorOptions& generatorOptions) {
  switch (detectFormat(input)) {
    case Format::Builtin:
      return synth::generate(std::string_view(input).substr(kBuiltinPrefix.size()),
                             generatorOptions);
    case Format::ExaBricks:
      return readExa(input);
    case Format::Amrex:
      return readAmrexPlotfile(input);
    case Format::Enzo:
      return readEnzo(input);
    case Format::Flash:
      return readFlash(input);
    case Format::Gerris:
      return readGerris(input);
  }
  throw InputError(input, "unknown input format");
}

}  // namespace amrstream::formats
