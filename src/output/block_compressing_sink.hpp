#pragma once
// Compresses one array's bytes into VTK's blocks (vtk_compression.hpp) on their way to a file.
// Bytes arrive in any amounts; they are cut into blocks of kBlockBytes and compressed a batch of
// blocks at a time, the blocks of a batch in parallel, while the caller goes on producing the
// next batch. The compressed blocks reach `out` in order. The block header is the caller's: its
// size follows from the byte count, and its compressed sizes are what finish() returns.
//
// Memory: two batches of input and one of output, whatever the array's size.

#include <tbb/task_group.h>

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "output/buffered_writer.hpp"
#include "output/byte_sink.hpp"
#include "output/vtk_compression.hpp"

namespace amrstream::output {

class BlockCompressingSink final : public ByteSink {
 public:
  // Blocks compressed together; a multiple of kBlockBytes.
  static constexpr std::size_t kBatchBytes = 128 * kBlockBytes;

  BlockCompressingSink(Compression compression, BufferedWriter& out, ZLibSettings zlib = {});
  // Waits for a batch still being compressed (after an exception) and drops it.
  ~BlockCompressingSink() noexcept override;
  BlockCompressingSink(const BlockCompressingSink&) = delete;
  BlockCompressingSink& operator=(const BlockCompressingSink&) = delete;

  void write(std::span<const std::byte> bytes) override;
  // Compresses and writes the rest (the last block may be partial) and returns the compressed
  // size of every block. The sink takes no more bytes afterwards.
  std::vector<std::uint64_t> finish();

 private:
  // Writes the batch in flight, if any, then starts compressing the filled batch.
  void startBatch();
  // Waits for the batch in flight and writes its blocks to out_.
  void writeBatchInFlight();

  Compression compression_;
  ZLibSettings zlib_;
  BufferedWriter& out_;
  std::vector<std::byte> filling_;
  std::vector<std::byte> inFlight_;
  CompressedBlocks compressed_;  // of inFlight_, once the task is done
  std::vector<std::uint64_t> sizes_;
  bool running_ = false;
  tbb::task_group tasks_;  // last: its batch uses the members above
};

}  // namespace amrstream::output
