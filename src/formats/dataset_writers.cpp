#include "formats/dataset_writers.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "amrstream/error.hpp"
#include "formats/amrex/amrex_writer.hpp"
#include "formats/enzo/enzo_writer.hpp"
#include "formats/exa/exa_format.hpp"
#include "formats/flash/flash_writer.hpp"

namespace amrstream::formats {

std::vector<std::string> writableFormats() { return {"exa", "flash", "enzo", "amrex"}; }

std::filesystem::path writtenPath(const std::filesystem::path& prefix, std::string_view format) {
  if (format == "exa") return prefix.string() + ".exa";
  if (format == "flash") return prefix.string() + ".h5";
  if (format == "enzo") return prefix;
  if (format == "amrex") return prefix.string() + ".plt";
  throw InputError(std::string(format), fmt::format("unknown output format (known: {})",
                                                    fmt::join(writableFormats(), ", ")));
}

std::filesystem::path writeFieldAs(const bricks::AmrField& field,
                                   const std::filesystem::path& prefix, std::string_view format) {
  const std::filesystem::path path = writtenPath(prefix, format);
  if (format == "exa") return writeExa(field, prefix);
  if (format == "flash") writeFlash(field, path);
  if (format == "enzo") writeEnzo(field, path);
  if (format == "amrex") writeAmrexPlotfile(field, path);
  return path;
}

}  // namespace amrstream::formats
