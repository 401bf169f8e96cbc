#include "output/buffered_writer.hpp"

namespace amrstream::output {

BufferedWriter::BufferedWriter(ByteSink& sink, std::size_t capacity)
    : sink_(sink), buffer_(capacity) {}

void BufferedWriter::write(std::span<const std::byte> bytes) {
  if (bytes.empty()) return;  // an empty vector's data() may be null, which memcpy rejects
  total_ += bytes.size();
  if (bytes.size() <= buffer_.size() - used_) {
    std::memcpy(buffer_.data() + used_, bytes.data(), bytes.size());
    used_ += bytes.size();
    return;
  }
  flush();
  if (bytes.size() >= buffer_.size()) {
    sink_.write(bytes);
  } else {
    std::memcpy(buffer_.data(), bytes.data(), bytes.size());
    used_ = bytes.size();
  }
}

void BufferedWriter::flush() {
  sink_.write(std::span(buffer_.data(), used_));
  used_ = 0;
}

}  // namespace amrstream::output
