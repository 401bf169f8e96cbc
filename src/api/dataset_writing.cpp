#include "amrstream/dataset_writing.hpp"

#include "api/handles.hpp"
#include "formats/dataset_writers.hpp"

namespace amrstream {

std::vector<std::string> writableFormats() { return formats::writableFormats(); }

std::filesystem::path writtenPath(const std::filesystem::path& prefix, std::string_view format) {
  return formats::writtenPath(prefix, format);
}

std::filesystem::path writeDataset(const Dataset& dataset, const std::filesystem::path& prefix,
                                   std::string_view format) {
  return formats::writeFieldAs(cellsOf(dataset), prefix, format);
}

}  // namespace amrstream
