#pragma once
// Where a reader puts the leaf cells it lays out and their values. A first (or only) read
// appends them. A second read of the same input against the cells a first read checked
// (ValueWindow::checked) writes values in place instead: it skips the pieces outside its window
// by their cell counts and compares the cells it lays out with the first read's.

#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <string>
#include <vector>

#include "bricks/amr_field.hpp"
#include "formats/value_window.hpp"

namespace amrstream::formats {

class CellSink {
 public:
  // `read`, when given, receives the channels' names.
  CellSink(const ValueWindow* window, std::string source, WindowedRead* read = nullptr);

  // A second read that lays out only the pieces it reads (the others: skip()).
  bool skipsPieces() const { return checked_ != nullptr; }
  // Room for `cells` cells (a first read).
  void reserve(std::size_t cells);
  // Adds a channel, every cell's value 0 until set.
  void addChannel(std::string name);
  // The next cell's index; on a second read, InputError unless it is the first read's.
  std::size_t cell(glm::ivec3 lower, std::uint8_t level);
  void set(std::size_t channel, std::size_t cell, float value);
  // A channel's values, one per cell, to be filled in place from any thread (after presize or
  // the cells' cell() calls); empty when the sink keeps no channels (ValueWindow::withChannels).
  std::span<float> values(std::size_t channel);
  // On a second read: the next `count` cells, of a piece not read.
  void skip(std::size_t count) { at_ += count; }

  // Pieces laid out in parallel, each at cells it knows: room for `cells` cells in all (on a
  // second read, InputError unless the first read's count), then place() for each cell, from
  // any thread, and set() for its values, instead of cell() and skip().
  void presize(std::size_t cells);
  void place(std::size_t at, glm::ivec3 lower, std::uint8_t level);
  // The field, checked (against the first read's cells on a second read).
  bricks::AmrField finish(WorldTransform transform);

  // The cells laid out so far (a first read), for checks before finish.
  const std::vector<glm::ivec3>& lowers() const { return lowers_; }
  const std::vector<std::uint8_t>& levels() const { return levels_; }

 private:
  const bricks::CheckedCells* checked_ = nullptr;
  const ValueWindow* window_ = nullptr;
  WindowedRead* read_ = nullptr;
  std::vector<std::string> names_;
  std::string source_;
  std::vector<glm::ivec3> lowers_;
  std::vector<std::uint8_t> levels_;
  std::vector<Channel> channels_;
  std::size_t at_ = 0;  // second read: the next cell
  bool presized_ = false;
};

}  // namespace amrstream::formats
