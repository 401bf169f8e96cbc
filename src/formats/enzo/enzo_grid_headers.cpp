#include "formats/enzo/enzo_grid_headers.hpp"

#include <tbb/parallel_for.h>

#include <memory>
#include <optional>
#include <unordered_map>
#include <utility>

#include "amrstream/error.hpp"

namespace amrstream::formats::enzo {

namespace {

// A file's headers and its root group's links, or nothing where they cannot be had.
struct FileHeaders {
  std::unique_ptr<Hdf5Headers> headers;
  std::unordered_map<std::string, std::uint64_t> root;
};

FileHeaders fileHeaders(const FieldFile& file) {
  FileHeaders found;
  if (file.id < 0) return found;
  try {
    found.headers = std::make_unique<Hdf5Headers>(file.path, file.id);
  } catch (const InputError&) {
    return found;  // libhdf5 tells, where the reader asks it
  }
  const auto links = rootLinks(file.id);
  if (!found.headers->usable() || !links) {
    found.headers.reset();
    return found;
  }
  for (const auto& [name, address] : *links) found.root.emplace("/" + name, address);
  return found;
}

std::vector<HeaderDataset> channelDatasets(const Hdf5Headers& headers, std::uint64_t group,
                                           std::span<const std::string> channels) {
  const auto links = headers.groupLinks(group);
  if (!links) return {};
  std::vector<HeaderDataset> datasets;
  datasets.reserve(channels.size());
  for (const std::string& channel : channels) {
    const auto link =
        std::ranges::find(*links, channel, &std::pair<std::string, std::uint64_t>::first);
    if (link == links->end()) return {};
    auto dataset = headers.contiguousDataset(link->second);
    if (!dataset) return {};
    datasets.push_back(std::move(*dataset));
  }
  return datasets;
}

}  // namespace

std::vector<GridDatasets> findGridDatasets(std::span<const FieldFile> files,
                                           std::span<const GridGroup> groups,
                                           std::span<const std::string> channels) {
  std::vector<FileHeaders> perFile;
  perFile.reserve(files.size());
  for (const FieldFile& file : files) perFile.push_back(fileHeaders(file));
  std::vector<GridDatasets> found(groups.size());
  tbb::parallel_for(std::size_t(0), groups.size(), [&](std::size_t n) {
    const GridGroup& group = groups[n];
    const FileHeaders& file = perFile[group.file];
    if (!file.headers) return;
    const auto at = file.root.find(group.name);
    if (at == file.root.end()) return;
    found[n].groupFound = true;
    found[n].fileBytes = file.headers->fileBytes();
    if (group.values) found[n].channels = channelDatasets(*file.headers, at->second, channels);
  });
  return found;
}

}  // namespace amrstream::formats::enzo
