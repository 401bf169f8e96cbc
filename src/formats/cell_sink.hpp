#pragma once
// Where a reader puts the leaf cells it lays out and their values, each piece of the input (a
// block, grid or box) at the cells it knows its place in, from any thread. A second read of the
// same input against the cells a first read checked (ValueWindow::checked) writes values in
// place instead: it lays out only the pieces in its window and compares their cells with the
// first read's.

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

  // A second read, which lays out only the pieces it reads.
  bool skipsPieces() const { return checked_ != nullptr; }
  // Adds a channel, every cell's value 0 until written.
  void addChannel(std::string name);
  // A channel's values, one per cell, to be filled in place from any thread after presize;
  // empty when the sink keeps no channels (ValueWindow::withChannels).
  std::span<float> values(std::size_t channel);

  // Room for `cells` cells in all (on a second read, InputError unless the first read's count),
  // then place() for each cell laid out.
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
};

}  // namespace amrstream::formats
