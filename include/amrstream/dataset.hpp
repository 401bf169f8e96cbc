#pragma once
// Datasets: the leaf cells of an AMR output with their channels and what the file says about
// itself, from any input the command line reads or from arrays (codes with no reader, yt).

#include <array>
#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bricks/amr_field.hpp"
#include "flow/vector_volume.hpp"
#include "synth/generators.hpp"

namespace amrstream {

using Dataset = bricks::AmrField;

// A FLASH, Enzo, AMReX, Gerris or ExaBricks file (recognised by content), or builtin:NAME sized
// by `builtin`. Throws InputError naming the input and the problem.
Dataset load(const std::string& input, const synth::GeneratorOptions& builtin = {});

// A dataset whose channels are read when they are needed: the cells with some channels, and a
// source of every channel by name (flow::fillVolumeValues takes it). ExaBricks files keep one
// channel a file, so a channel is read from its file only when asked for and freed after; other
// inputs are loaded whole and their channels given from memory.
struct DeferredDataset {
  // Without channels (an .exa: add those needed before the volume's values with addChannel) or
  // with all; release it once the volume's layout and the seeds are made (`channels` keeps what
  // it still needs).
  std::shared_ptr<Dataset> cells;
  flow::ChannelCatalog catalog;  // every channel
  flow::ChannelSource channels;  // any channel, by name
};

DeferredDataset loadDeferred(const std::string& input, const synth::GeneratorOptions& builtin);

// Leaf cells given as arrays. Levels count up from the coarsest (0, as yt, Enzo and AMReX number
// them), each twice as fine as the one before; corners are the cells' lower corners in cells of
// the finest level given, counted from `origin`.
struct CellArrays {
  std::vector<glm::ivec3> corners;
  std::vector<int> levels;
  std::vector<bricks::Channel> channels;
  glm::dvec3 origin{0.0};       // physical position of corner (0, 0, 0)
  glm::dvec3 finestWidth{1.0};  // physical width of a finest cell, per axis
  std::string source = "arrays";
  std::string format = "arrays";
  std::optional<double> time;
  std::string timeUnit, lengthUnit;
  std::optional<std::array<bool, 3>> periodic;  // unset: the source says nothing
};

// Throws InputError (naming `source`) for levels out of range and everything AmrField rejects:
// misaligned or overlapping cells, non-finite values, channel sizes that differ from the cells'.
Dataset fromCells(CellArrays cells);

}  // namespace amrstream
