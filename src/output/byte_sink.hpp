#pragma once
// Where a BufferedWriter sends its bytes: a file, or a compressor in front of one.

#include <cstddef>
#include <span>

namespace amrstream::output {

class ByteSink {
 public:
  virtual ~ByteSink() = default;
  virtual void write(std::span<const std::byte> bytes) = 0;
};

}  // namespace amrstream::output
