#pragma once
// The field values of Enzo grids, gathered on one thread and read on all. Each grid's datasets
// are opened and checked where they are added (libhdf5 is not thread safe); a contiguous,
// unfiltered dataset of the machine's float32 or float64 is queued to be read through its file
// offset (float_runs.hpp), any other is read with H5Dread at once. run() reads the queue, file by
// file, each file's datasets in pieces on all cores. Used only by the Enzo reader.

#include <hdf5.h>

#include <filesystem>
#include <glm/glm.hpp>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "formats/float_runs.hpp"

namespace amrstream::formats::enzo {

class FieldReads {
 public:
  explicit FieldReads(std::vector<std::string> channels) : channels_(std::move(channels)) {}

  // The fields of the grid in group `group` (named `groupName`) of `file`, with `dims` active
  // zones (x y z; a 2D grid's datasets may be (ny, nx)), channel c's values into `into[c]`
  // (room for every zone, x fastest). Throws InputError naming the file and dataset when one is
  // missing, misshapen, not floating point or not stored, and for a value read here that is not
  // finite or beyond the float range.
  void add(hid_t group, const std::filesystem::path& file, const std::string& groupName,
           glm::ivec3 dims, int axes, std::span<float* const> into);

  // Reads what add() queued. Throws InputError naming the file, dataset and zone of a value that
  // is not finite or beyond the float range (the first such of the first file that has one).
  void run() const;

 private:
  struct Source {
    std::string dataset;  // GROUP/NAME
    glm::ivec3 dims;
    int axes;
  };
  struct FileReads {
    std::filesystem::path file;
    int valueBytes = 4;
    std::vector<FloatRun> runs;
    std::vector<Source> sources;  // per run
  };
  void queue(const std::filesystem::path& file, int valueBytes, FloatRun run, Source source);

  std::vector<std::string> channels_;
  std::vector<FileReads> files_;
  std::map<std::pair<std::string, int>, std::size_t> fileIndex_;  // into files_
};

}  // namespace amrstream::formats::enzo
