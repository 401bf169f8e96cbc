#pragma once
// A dataset whose channels are read when they are needed: the cells with some channels, and a
// source of every channel by name (flow::fillVolumeValues takes it). ExaBricks files keep one
// channel a file, so a channel is read from its file only when asked for and freed after; other
// inputs are loaded whole and their channels given from memory.

#include <memory>
#include <string>

#include "amrstream/builtin.hpp"
#include "bricks/amr_field.hpp"
#include "flow/vector_volume.hpp"

namespace amrstream {

struct DeferredDataset {
  // Without channels (an .exa: add those needed before the volume's values with addChannel) or
  // with all; release it once the volume's layout and the seeds are made (`channels` keeps what
  // it still needs).
  std::shared_ptr<bricks::AmrField> cells;
  flow::ChannelCatalog catalog;  // every channel
  flow::ChannelSource channels;  // any channel, by name
};

DeferredDataset loadDeferred(const std::string& input, const BuiltinOptions& builtin);

}  // namespace amrstream
