#include "formats/load_input.hpp"

#include <fmt/format.h>
#include <hdf5.h>

#include <filesystem>
#include <fstream>
#include <optional>

#include "amrstream/error.hpp"
#include "formats/amrex/amrex_reader.hpp"
#include "formats/enzo/enzo_reader.hpp"
#include "formats/exa/exa_format.hpp"
#include "formats/flash/flash_reader.hpp"
#include "formats/gerris/gerris_reader.hpp"
#include "formats/hdf5_handle.hpp"
#include "util/input_file.hpp"

namespace amrstream::formats {

namespace {

namespace fs = std::filesystem;
constexpr std::string_view kBuiltinPrefix = "builtin:";
constexpr std::string_view kFormatsTried =
    "amrstream reads builtin:KIND, a .exa, an AMReX plotfile folder, an Enzo parameter file (or "
    "a file beside it), FLASH HDF5 and a Gerris text dump";

[[noreturn]] void notRecognised(const std::string& input, const std::string& why) {
  throw InputError(input, fmt::format("format not recognised: {}; {}", why, kFormatsTried));
}

// The first `n` bytes of a regular file (fewer when it is shorter).
std::string firstBytes(const fs::path& path, std::size_t n) {
  std::ifstream in(path, std::ios::binary);
  std::string bytes(n, '\0');
  in.read(bytes.data(), std::streamsize(n));
  bytes.resize(std::size_t(in.gcount()));
  return bytes;
}

bool isHdf5(const fs::path& path) { return firstBytes(path, 8) == "\x89HDF\r\n\x1a\n"; }

// FLASH files, plotfiles and checkpoints alike, list their variables in 'unknown names'.
bool isFlash(const fs::path& path) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const Hdf5Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (!file.valid())
    throw InputError(path.string(), "an HDF5 file that HDF5 cannot open (truncated or corrupt?)");
  return H5Lexists(file.get(), "unknown names", H5P_DEFAULT) > 0;
}

// Enzo writes PREFIX (parameters), PREFIX.hierarchy, PREFIX.harrays and PREFIX.cpuNNNN.
bool isEnzo(const fs::path& path) {
  const std::string ext = path.extension().string();
  if (ext == ".hierarchy" || ext == ".harrays" || ext.starts_with(".cpu")) return true;
  if (enzoCompanionOf(path)) return true;
  std::error_code error;
  return fs::exists(path.string() + ".hierarchy", error);
}

bool isAmrexPlotfile(const fs::path& directory) {
  std::error_code error;
  const fs::path header = directory / "Header";
  return fs::is_regular_file(header, error) && firstBytes(header, 9) == "HyperCLaw";
}

// The Enzo parameter file in `directory` (the file beside a .hierarchy), if there is one.
std::optional<fs::path> enzoParametersIn(const fs::path& directory) {
  std::error_code error;
  for (fs::directory_iterator it(directory, error), end; !error && it != end; it.increment(error)) {
    const fs::path file = it->path();
    if (file.extension() != ".hierarchy") continue;
    fs::path parameters = file;
    parameters.replace_extension();
    if (fs::is_regular_file(parameters, error)) return parameters;
  }
  return std::nullopt;
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
  std::error_code error;
  if (fs::is_directory(path, error)) {
    if (isAmrexPlotfile(path)) return Format::Amrex;
    if (const auto parameters = enzoParametersIn(path))
      throw InputError(input, fmt::format("an Enzo output folder: pass its parameter file, {}",
                                          parameters->string()));
    throw InputError(input,
                     "a folder, but not an AMReX plotfile (no Header starting with HyperCLaw); "
                     "pass a dataset file in it");
  }
  regularFileSize(path);  // a missing path, a FIFO or a device is refused before it is opened
  if (path.filename() == "Header" && firstBytes(path, 9) == "HyperCLaw")
    throw InputError(input,
                     fmt::format("an AMReX plotfile's Header: pass the plotfile's "
                                 "folder, {}",
                                 path.parent_path().empty() ? "." : path.parent_path().string()));
  if (path.extension() == ".exa") return Format::ExaBricks;
  if (isEnzo(path)) return Format::Enzo;
  if (isHdf5(path)) {
    if (isFlash(path)) return Format::Flash;
    notRecognised(input, "an HDF5 file without FLASH's 'unknown names' dataset");
  }
  if (firstBytes(path, 4) == "# 1:") return Format::Gerris;
  notRecognised(input, "no known extension or signature");
}

bool readsValueWindows(Format format) {
  return format == Format::Amrex || format == Format::Enzo || format == Format::Flash;
}

bricks::AmrField loadInput(const std::string& input, const BuiltinOptions& generatorOptions,
                           const ValueWindow* window, WindowedRead* read) {
  switch (detectFormat(input)) {
    case Format::Builtin:
      return synth::generate(std::string_view(input).substr(kBuiltinPrefix.size()),
                             generatorOptions);
    case Format::ExaBricks:
      return readExa(input);
    case Format::Amrex:
      return readAmrexPlotfile(input, window, read);
    case Format::Enzo:
      return readEnzo(input, window, read);
    case Format::Flash:
      return readFlash(input, window, read);
    case Format::Gerris:
      return readGerris(input);
  }
  throw InputError(input, "unknown input format");
}

}  // namespace amrstream::formats
