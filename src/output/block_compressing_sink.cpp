#include "output/block_compressing_sink.hpp"

#include <algorithm>
#include <utility>

namespace amrstream::output {

BlockCompressingSink::BlockCompressingSink(Compression compression, BufferedWriter& out,
                                           ZLibSettings zlib)
    : compression_(compression), zlib_(zlib), out_(out) {
  filling_.reserve(kBatchBytes);
  inFlight_.reserve(kBatchBytes);
}

BlockCompressingSink::~BlockCompressingSink() noexcept {
  if (!running_) return;
  tasks_.cancel();
  try {
    tasks_.wait();
  } catch (...) {  // an exception is already on its way out; this one would end the program
  }
}

void BlockCompressingSink::write(std::span<const std::byte> bytes) {
  while (!bytes.empty()) {
    const std::size_t take = std::min(bytes.size(), kBatchBytes - filling_.size());
    filling_.insert(filling_.end(), bytes.begin(), bytes.begin() + take);
    bytes = bytes.subspan(take);
    if (filling_.size() == kBatchBytes) startBatch();
  }
}

std::vector<std::uint64_t> BlockCompressingSink::finish() {
  if (!filling_.empty()) startBatch();
  writeBatchInFlight();
  return std::move(sizes_);
}

void BlockCompressingSink::startBatch() {
  writeBatchInFlight();
  std::swap(filling_, inFlight_);
  filling_.clear();
  running_ = true;
  tasks_.run([this] { compressed_ = compressBlocks(compression_, inFlight_, zlib_); });
}

void BlockCompressingSink::writeBatchInFlight() {
  if (!running_) return;
  running_ = false;
  tasks_.wait();
  out_.write(compressed_.bytes);
  sizes_.insert(sizes_.end(), compressed_.sizes.begin(), compressed_.sizes.end());
}

}  // namespace amrstream::output
