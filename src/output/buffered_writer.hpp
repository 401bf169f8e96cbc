#pragma once
// Collects small writes (one float at a time) into large ones, so streaming an array value by
// value costs a memcpy, not a system call (or a call into the compressor). Counts every byte it
// accepts.

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <string_view>
#include <type_traits>
#include <vector>

#include "output/byte_sink.hpp"

namespace amrstream::output {

class BufferedWriter {
 public:
  explicit BufferedWriter(ByteSink& sink, std::size_t capacity = std::size_t(1) << 20);
  BufferedWriter(const BufferedWriter&) = delete;
  BufferedWriter& operator=(const BufferedWriter&) = delete;

  void write(std::span<const std::byte> bytes);
  void write(std::string_view text) { write(std::as_bytes(std::span(text))); }

  // Host byte order; callers that need a given order check std::endian.
  template <class T>
  requires std::is_trivially_copyable_v<T>
  void put(const T& value) {
    if (buffer_.size() - used_ < sizeof(T)) flush();
    std::memcpy(buffer_.data() + used_, &value, sizeof(T));
    used_ += sizeof(T);
    total_ += sizeof(T);
  }

  void flush();
  std::uint64_t bytesWritten() const { return total_; }

 private:
  ByteSink& sink_;
  std::vector<std::byte> buffer_;
  std::size_t used_ = 0;
  std::uint64_t total_ = 0;
};

}  // namespace amrstream::output
