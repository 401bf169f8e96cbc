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

void CellSink::reserve(std::size_t cells) {
  if (checked_) return;
  lowers_.reserve(cells);
  levels_.reserve(cells);
  for (Channel& channel : channels_) channel.values.reserve(cells);
}

void CellSink::addChannel(std::string name) {
  names_.push_back(name);
  if (window_ && !window_->withChannels) return;
  channels_.push_back(
      {std::move(name), std::vector<float>(checked_ ? checked_->lowers.size() : lowers_.size())});
}

void CellSink::set(std::size_t channel, std::size_t cell, float value) {
  if (!channels_.empty()) channels_[channel].values[cell] = value;
}

std::span<float> CellSink::values(std::size_t channel) {
  if (channels_.empty()) return {};
  return channels_[channel].values;
}

std::size_t CellSink::cell(glm::ivec3 lower, std::uint8_t level) {
  if (checked_) {
    if (at_ >= checked_->lowers.size() || checked_->lowers[at_] != lower ||
        checked_->levels[at_] != level)
      differs(source_);
    return at_++;
  }
  lowers_.push_back(lower);
  levels_.push_back(level);
  for (Channel& channel : channels_) channel.values.push_back(0.0f);
  return lowers_.size() - 1;
}

void CellSink::presize(std::size_t cells) {
  presized_ = true;
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
    if (!presized_ && at_ != checked_->lowers.size()) differs(source_);
    lowers_ = checked_->lowers;
    levels_ = checked_->levels;
  }
  return checkedField(std::move(lowers_), std::move(levels_), std::move(channels_), transform,
                      std::move(source_), window_);
}

}  // namespace amrstream::formats
