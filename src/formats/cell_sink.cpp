#include "formats/cell_sink.hpp"

#include <utility>

#include "amrstream/error.hpp"
#include "util/huge_pages.hpp"

namespace amrstream::formats {

namespace {

[[noreturn]] void differs(const std::string& source) {
  throw InputError(source, "its cells differ from those of a first read (did it change?)");
}

// The field a reader read, checked: against `window->checked` when there is one.
bricks::AmrField checkedField(std::vector<glm::ivec3> lowers, std::vector<std::uint8_t> levels,
                              std::vector<Channel> channels, WorldTransform transform,
                              std::string source, const ValueWindow* window) {
  if (window && window->checked)
    return bricks::AmrField(std::move(lowers), std::move(levels), std::move(channels), transform,
                            std::move(source), *window->checked);
  return bricks::AmrField(std::move(lowers), std::move(levels), std::move(channels), transform,
                          std::move(source));
}

}  // namespace

CellSink::CellSink(const ValueWindow* window, std::string source, WindowedRead* read)
    : checked_(window ? window->checked : nullptr),
      window_(window),
      read_(read),
      source_(std::move(source)) {}

void CellSink::addChannel(std::string name) {
  names_.push_back(name);
  if (window_ && !window_->withChannels) return;
  Channel channel{std::move(name), {}};
  resizeInHugePages(channel.values, checked_ ? checked_->lowers.size() : lowers_.size());
  channels_.push_back(std::move(channel));
}

std::span<float> CellSink::values(std::size_t channel) {
  if (channels_.empty()) return {};
  return channels_[channel].values;
}

void CellSink::presize(std::size_t cells) {
  if (checked_) {
    if (cells != checked_->lowers.size()) differs(source_);
    return;
  }
  resizeInHugePages(lowers_, cells);
  resizeInHugePages(levels_, cells);
  for (Channel& channel : channels_) resizeInHugePages(channel.values, cells);
}

void CellSink::place(std::size_t at, glm::ivec3 lower, std::uint8_t level) {
  if (checked_) {
    if (checked_->lowers[at] != lower || checked_->levels[at] != level) differs(source_);
    return;
  }
  lowers_[at] = lower;
  levels_[at] = level;
}

bricks::AmrField CellSink::finish(WorldTransform transform) {
  if (read_) read_->channels = names_;
  if (checked_) {
    lowers_ = checked_->lowers;
    levels_ = checked_->levels;
  }
  return checkedField(std::move(lowers_), std::move(levels_), std::move(channels_), transform,
                      std::move(source_), window_);
}

}  // namespace amrstream::formats
