#pragma once
// The AMR model: a set of leaf cells, each with an integer lower corner in finest-cell units, a
// level (0 = finest, a level-L cell is 2^L finest cells wide) and one float per named channel,
// plus a world transform to the input's physical coordinates.
//
// Invariants kept by construction (violations throw InputError naming the source):
// at least one cell; every cell aligned to its level's grid; no two cells overlap (no duplicates,
// no cell inside a coarser one); every channel has one finite value per cell; channel names are
// unique and non-empty.
//
// Beside the cells it carries what the input says about itself (DatasetInfo: time, units,
// periodicity, the file's level numbers), set by the reader; until then it only numbers levels
// as above.

#include <array>
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "amrstream/cell_types.hpp"
#include "amrstream/dataset_info.hpp"

namespace amrstream::bricks {

// Cells' coordinates are 32-bit; bricks and regions are centred on the domain and regions use
// doubled coordinates (docs/architecture.md, "Positions"), hence these limits.
inline constexpr int kMaxLevel = 29;  // coarsest supported level (cell width 2^29)
inline constexpr int kMaxExtentBits =
    30;  // the cells' bounding box spans at most 2^30 finest cells

// The corners and levels of cells an AmrField has checked, kept to check a second read of the
// same input cheaply (an MPI rank reads an output twice: its layout, then its part's values).
struct CheckedCells {
  std::vector<glm::ivec3> lowers;
  std::vector<std::uint8_t> levels;
};

class LevelTiling;  // level_corner_set.hpp

class AmrField {
 public:
  // `source` names where the data came from (a path or builtin:NAME); it prefixes every error.
  AmrField(std::vector<glm::ivec3> lowers, std::vector<std::uint8_t> levels,
           std::vector<Channel> channels, WorldTransform transform, std::string source);
  // The same with what the input says of itself, known before the cells are checked: errors
  // then name levels as the input numbers them.
  AmrField(std::vector<glm::ivec3> lowers, std::vector<std::uint8_t> levels,
           std::vector<Channel> channels, WorldTransform transform, std::string source,
           DatasetInfo info);

  // The same for cells that must equal `checked`, whose overlap check (the longest) is then
  // skipped; InputError naming the source when they differ.
  AmrField(std::vector<glm::ivec3> lowers, std::vector<std::uint8_t> levels,
           std::vector<Channel> channels, WorldTransform transform, std::string source,
           const CheckedCells& checked);

  std::size_t cellCount() const { return lowers_.size(); }
  std::span<const glm::ivec3> lowers() const { return lowers_; }
  std::span<const std::uint8_t> levels() const { return levels_; }
  static int cellWidth(int level) { return 1 << level; }

  const std::vector<Channel>& channels() const { return channels_; }
  // Adds a channel, checked as the constructor checks channels (InputError naming the source).
  // Readers add channels after the cells so that the cells' checks, whose sets are the largest
  // transient of loading, do not take their memory beside the channels'.
  void addChannel(Channel channel);
  std::optional<std::size_t> findChannel(std::string_view name) const;
  // Throws InputError listing the available channels when `name` is absent.
  const Channel& channel(std::string_view name) const;

  const WorldTransform& transform() const { return transform_; }
  const std::string& source() const { return source_; }

  const DatasetInfo& info() const { return info_; }
  void setInfo(DatasetInfo info) { info_ = std::move(info); }

  // Seconds the constructor spent on its checks: of the cells (counts, levels, alignment, the
  // channels given to it, the bounds) and of overlaps (none for cells a first read checked).
  struct CheckSeconds {
    double cells = 0.0;
    double overlaps = 0.0;
  };
  CheckSeconds checkSeconds() const { return checkSeconds_; }

  CellBox bounds() const { return bounds_; }  // bounding box of all cells
  int coarsestLevel() const { return coarsest_; }
  int finestLevel() const { return finest_; }
  std::vector<std::size_t> cellsPerLevel() const;  // indexed by level, up to coarsestLevel()

 private:
  AmrField(std::vector<glm::ivec3> lowers, std::vector<std::uint8_t> levels,
           std::vector<Channel> channels, WorldTransform transform, std::string source,
           const CheckedCells* checked);
  // Per level, the box of its cells' corners (defined in amr_field.cpp).
  struct LevelBoxes;

  // Also sets bounds_, coarsest_ and finest_.
  void validate(const CheckedCells* checked = nullptr);
  // The steps of validate(), in its order: the counts of cells and levels and the channels'
  // shapes and names; the cells' levels and alignment; the levels' boxes, then all cells' box
  // within the supported extent; no two cells overlapping.
  void checkCellCounts() const;
  void checkCellLevels() const;
  LevelBoxes levelBoxes() const;
  CellBox checkedBounds(const LevelBoxes& boxes) const;
  void checkOverlaps(const LevelBoxes& boxes) const;
  std::array<std::size_t, kMaxLevel + 1> tileRuns(const std::vector<LevelTiling>& tilings) const;
  void checkChannelShape(const Channel& channel) const;
  void checkChannelValues(const Channel& channel) const;
  void validateTransform() const;

  std::vector<glm::ivec3> lowers_;
  std::vector<std::uint8_t> levels_;
  std::vector<Channel> channels_;
  WorldTransform transform_;
  std::string source_;
  CellBox bounds_;
  int coarsest_ = 0, finest_ = 0;  // the levels of the widest and narrowest cells
  CheckSeconds checkSeconds_;
  DatasetInfo info_;
};

}  // namespace amrstream::bricks
