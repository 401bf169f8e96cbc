#pragma once
// Datasets: the leaf cells of an AMR output with their channels and what the file says about
// itself, from any input the command line reads or from arrays (codes with no reader, yt).

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <glm/glm.hpp>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "amrstream/builtin.hpp"
#include "amrstream/cell_types.hpp"
#include "amrstream/dataset_info.hpp"

namespace amrstream {

// The leaf cells of an AMR dataset: each has an integer lower corner in finest-cell units, a
// level (0 = finest: a level-L cell is 2^L finest cells wide) and one float per channel. The cells
// tile the covered domain without overlap, and every value is finite. A Dataset is a handle:
// copies share the cells, which never change.
class Dataset {
 public:
  const std::string& source() const;  // the path or builtin:NAME it came from
  const DatasetInfo& info() const;    // what the file says of itself
  std::size_t cellCount() const;
  std::span<const glm::ivec3> corners() const;   // lower corners, finest-cell units
  std::span<const std::uint8_t> levels() const;  // 0 = finest (info().fileLevel: the file's)
  std::vector<std::string> channelNames() const;
  bool hasChannel(std::string_view name) const;
  // One value per cell, in cell order. Throws InputError listing the channels when absent.
  std::span<const float> channel(std::string_view name) const;
  const WorldTransform& transform() const;  // cell units to physical coordinates
  CellBox bounds() const;                   // the cells' bounding box, finest-cell units
  // Seconds loading spent checking the cells (levels, alignment, bounds) and that none overlap.
  std::pair<double, double> checkSeconds() const;
  glm::dvec3 lower() const;  // the bounding box in physical coordinates
  glm::dvec3 upper() const;
  int finestLevel() const;    // 0 unless the finest cells are coarser than the unit
  int coarsestLevel() const;  // internal numbering
  std::vector<std::size_t> cellsPerLevel() const;  // indexed by internal level

  struct Impl;  // the library's: src/api/handles.hpp
  explicit Dataset(std::shared_ptr<const Impl> impl);
  const Impl& impl() const { return *impl_; }

 private:
  std::shared_ptr<const Impl> impl_;
};

// A FLASH, Enzo, AMReX, Gerris or ExaBricks file (recognised by content), or builtin:NAME sized
// by `builtin`, with the units `units` declares where the file states none (a NAME there is a
// channel, or the name of the vector the field takes by default). Throws InputError naming the
// input and the problem.
Dataset load(const std::string& input, const BuiltinOptions& builtin = {},
             const DeclaredUnits& units = {});

// The existing files and directories that reading `input` may open: nothing for builtin:KIND;
// an AMReX plotfile directory itself (everything under it); an ExaBricks .exa with the cells and
// scalar files it names; an Enzo dataset's parameter file, .hierarchy, .harrays and .cpuNNNN
// files (whichever of them the input names); any other file alone. Throws InputError, as loading
// would, for an input that does not exist or is in no known format. Front ends refuse an output
// that would replace one of them.
std::vector<std::filesystem::path> datasetFiles(const std::string& input);

// The name of the input's format ("FLASH", "Enzo", "AMReX", "Gerris", "ExaBricks", "builtin"),
// recognised by content as load() does.
std::string formatName(const std::string& input);

// Writes the dataset as ExaBricks files: PREFIX.exa, PREFIX.cells and PREFIX.NAME.scalars per
// channel, each through a temporary file. Returns the .exa's path.
std::filesystem::path writeExaBricks(const Dataset& dataset, const std::filesystem::path& prefix);

// Leaf cells given as arrays. Levels count up from the coarsest (0, as yt, Enzo and AMReX number
// them), each twice as fine as the one before; corners are the cells' lower corners in cells of
// the finest level given, counted from `origin`.
struct CellArrays {
  std::vector<glm::ivec3> corners;
  std::vector<int> levels;
  std::vector<Channel> channels;
  glm::dvec3 origin{0.0};       // physical position of corner (0, 0, 0)
  glm::dvec3 finestWidth{1.0};  // physical width of a finest cell, per axis
  std::string source = "arrays";
  std::string format = "arrays";
  std::optional<double> time;
  std::string timeUnit, lengthUnit;
  std::optional<double> lengthUnitCentimetres;            // where the length unit is known
  std::map<std::string, std::string, std::less<>> units;  // a channel's unit, by its name
  std::optional<std::array<bool, 3>> periodic;            // unset: the source says nothing
  int dimensions = 3;  // 2: planar data held as a slab across z = 0 (DatasetInfo::dimensions)
};

// Throws InputError (naming `source`) for levels out of range and everything a Dataset rejects:
// misaligned or overlapping cells, non-finite values, channel sizes that differ from the cells'.
Dataset fromCells(CellArrays cells);

// What `amrstream info` reports of a dataset beyond its own accessors: each channel's range, and
// the bricks and active brick regions its cells make (built to measure them).
struct DatasetSummary {
  struct ChannelRange {
    std::string name;
    float min = 0.0f, max = 0.0f;
  };
  std::vector<ChannelRange> channels;
  std::size_t bricks = 0, largestBrickCells = 0;
  double bricksSeconds = 0.0;
  std::size_t regions = 0, regionBrickEntries = 0, largestRegionBricks = 0, treeNodes = 0;
  double regionsSeconds = 0.0;
};
DatasetSummary summarize(const Dataset& dataset);

}  // namespace amrstream
