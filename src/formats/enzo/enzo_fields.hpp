#pragma once
// The field values of Enzo grids, gathered on one thread and read on all. Each grid's datasets
// are checked where they are added: opened through libhdf5 (not thread safe) there, or found
// beforehand from their object headers (enzo_grid_headers.hpp); a contiguous,
// unfiltered dataset of IEEE float32 or float64 (either byte order) is queued to be read through
// its file offset (float_runs.hpp), any other is read with H5Dread at once. The queued values are
// read in batches of a few MiB per file, on all cores, while the next grids are added: the reading
// overlaps libhdf5's work on one thread. Used only by the Enzo reader.

#include <hdf5.h>
#include <tbb/task_group.h>

#include <cstdint>
#include <deque>
#include <filesystem>
#include <glm/glm.hpp>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "formats/float_runs.hpp"
#include "formats/hdf5_checks.hpp"
#include "formats/hdf5_headers.hpp"

namespace amrstream::formats::enzo {

class FieldReads {
 public:
  // Values per batch: enough that each batch keeps every core busy, few enough that the reading
  // starts while most grids are still to be added.
  static constexpr std::uint64_t kBatchValues = std::uint64_t(1) << 22;

  explicit FieldReads(std::vector<std::string> channels, std::uint64_t batchValues = kBatchValues)
      : channels_(std::move(channels)), batchValues_(batchValues) {}
  FieldReads(const FieldReads&) = delete;
  FieldReads& operator=(const FieldReads&) = delete;
  // Waits for the batches still being read (after an error that ends the reading).
  ~FieldReads();

  // The fields of the grid in group `group` (named `groupName`) of `file`, with `dims` active
  // zones (x y z; a 2D grid's datasets may be (ny, nx)), channel c's values into `into[c]`
  // (room for every zone, x fastest, untouched by anything else until run() returns). Throws
  // InputError naming the file and dataset when one is missing, misshapen, not floating point or
  // not stored, and for a value read here that is not finite or beyond the float range.
  void add(hid_t group, const std::filesystem::path& file, const std::string& groupName,
           glm::ivec3 dims, int axes, std::span<float* const> into);

  // The same for a grid whose datasets were read from their object headers (`datasets`, one per
  // channel, in a file of `fileBytes`), with the same checks and errors.
  void addInPlace(const std::filesystem::path& file, const std::string& groupName, glm::ivec3 dims,
                  int axes, std::span<float* const> into, std::span<const HeaderDataset> datasets,
                  std::uint64_t fileBytes);

  // Reads what add() queued and has not read yet, and waits for all of it. Throws InputError
  // naming the file, dataset and zone of a value that is not finite or beyond the float range
  // (the first such of the first file, in the order add() met them, that has one).
  void run();

 private:
  struct Source {
    std::string dataset;  // GROUP/NAME
    glm::ivec3 dims;
    int axes;
  };
  struct FileReads {
    std::filesystem::path file;
    FloatEncoding encoding;
    std::vector<Source> sources;  // per run queued
    std::vector<FloatRun> pending;
    std::uint64_t pendingValues = 0;
  };
  // Runs of one file handed to the cores together; `bad`: the first unusable value they met.
  struct Batch {
    std::size_t file;
    std::size_t firstRun;  // among the file's runs
    std::vector<FloatRun> runs;
    std::optional<UnusableValue> bad;
  };
  // Queues the dataset `stored` (named `what`) for reading into `into`; false when it must be
  // read with H5Dread.
  bool queueInPlace(const StoredDataset& stored, const std::filesystem::path& file,
                    const std::string& what, glm::ivec3 dims, int axes, float* into);
  void queue(const std::filesystem::path& file, FloatEncoding encoding, FloatRun run,
             Source source);
  void launch(std::size_t file);

  std::vector<std::string> channels_;
  std::uint64_t batchValues_;
  std::deque<FileReads> files_;  // a batch being read keeps its file's address
  std::map<std::pair<std::string, FloatEncoding>, std::size_t> fileIndex_;  // into files_
  std::deque<Batch> batches_;                                               // launched, in order
  tbb::task_group reading_;
};

}  // namespace amrstream::formats::enzo
