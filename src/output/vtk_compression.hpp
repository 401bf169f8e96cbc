#pragma once
// Compressed data arrays as VTK's XML writers store them (vtkZLibDataCompressor,
// vtkLZ4DataCompressor), independent of where the bytes go: the block layout, its header, and
// compression of many blocks at once.
//
// An array's raw bytes are cut into blocks of kBlockBytes (the last one may be shorter), and each
// block is compressed on its own: zlib as compress2() writes it (a zlib stream, RFC 1950: 2-byte
// header, deflate data, Adler-32; VTK 9.1 writes level 5, header bytes 78 9C), LZ4 as
// LZ4_compress_default() writes it (the raw block format, no frame; VTK's blocks start with the
// LZ4 token directly). Any zlib inflate reads a stream whatever level or strategy made it. The
// compressed array is a header of 3 + n integers (UInt64 or UInt32, the file's header_type, in the
// file's byte order) followed by the n compressed blocks:
//
//   [n, block size, last block size, compressed size of block 0, ..., of block n-1]
//
// VTK 9.1 writes block size 32768 always, and "last block size" 0 when the last block is full
// (an array of exactly 32768 bytes is [1, 32768, 0, c]), its size when it is partial (20 bytes
// give [1, 32768, 20, c]); an empty array is [0, 32768, 0] with no blocks. Checked with
// python3-vtk9 9.1.0 (vtkXMLPolyDataWriter) on raw appended files.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace amrstream::output {

enum class Compression { None, ZLib, LZ4 };

// "none", "zlib", "lz4": the names the CLI takes and prints.
std::optional<Compression> compressionNamed(std::string_view name);
std::string_view compressionName(Compression compression);
// The VTKFile compressor attribute: "vtkZLibDataCompressor", "vtkLZ4DataCompressor"; "" for None.
std::string_view vtkCompressorName(Compression compression);
std::optional<Compression> compressionOfVtkCompressor(std::string_view className);

inline constexpr std::uint64_t kBlockBytes = 32768;

// How a block is deflated into the zlib format (LZ4 has no settings). Level 1 of libdeflate: on
// trace data (bench/compression, docs/formats.md) higher levels are slower for files at most a
// few per cent smaller.
struct ZLibSettings {
  int level = 1;
};

// The most output one compressed byte can inflate to: deflate's limit is 1032:1 (zlib's technical
// notes), LZ4's is below 255:1 (each extra byte of a match length adds at most 255). Reading uses
// them to refuse, before allocating, headers that no real stream can satisfy.
std::uint64_t maxInflationRatio(Compression compression);

// Thrown for compressed data that is not what its header says; the reader adds file and array.
class CompressedDataError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The header of one compressed array.
struct BlockHeader {
  std::uint64_t blockCount = 0;
  std::uint64_t blockBytes = kBlockBytes;  // uncompressed size of every block but a partial last
  std::uint64_t lastBlockBytes = 0;        // uncompressed size of a partial last block, else 0
  std::vector<std::uint64_t> compressedSizes;

  // The layout VTK writes for `uncompressedBytes` bytes; compressedSizes left empty.
  static BlockHeader forBytes(std::uint64_t uncompressedBytes);

  std::uint64_t uncompressedBytesOf(std::uint64_t block) const;
  // Throws CompressedDataError when the sizes overflow.
  std::uint64_t uncompressedBytes() const;
  std::uint64_t compressedBytes() const;
};

// Upper bound of one block's compressed size.
std::size_t maxCompressedBytes(Compression compression, std::size_t uncompressedBytes);

// Compresses one block (at most kBlockBytes) into `out`, which holds maxCompressedBytes(); returns
// the compressed size. Thread-safe.
std::size_t compressBlock(Compression compression, std::span<const std::byte> in,
                          std::span<std::byte> out, ZLibSettings zlib = {});

// Compresses `input` cut into blocks of kBlockBytes, the blocks in parallel (TBB).
struct CompressedBlocks {
  std::vector<std::byte> bytes;  // the compressed blocks, one after the other
  std::vector<std::uint64_t> sizes;
};
CompressedBlocks compressBlocks(Compression compression, std::span<const std::byte> input,
                                ZLibSettings zlib = {});

// The compressed blocks of one array, checked against its header: every size adds up, fits in
// `data`, and no block claims more than it can inflate to. Views `data`, which must outlive it.
class BlockReader {
 public:
  // Throws CompressedDataError saying what does not fit.
  BlockReader(Compression compression, BlockHeader header, std::span<const std::byte> data);

  std::uint64_t uncompressedBytes() const { return uncompressedBytes_; }

  // Calls consume with the uncompressed bytes in order, a batch of blocks at a time (the blocks
  // of a batch decompressed in parallel), so memory beyond the caller's is one batch. Throws
  // CompressedDataError naming the first block that is corrupt or inflates to another size than
  // the header says.
  template <class Consume>
  void forEachBatch(Consume&& consume) const {
    std::vector<std::byte> batch;
    for (std::uint64_t first = 0; first < header_.blockCount;) {
      const std::uint64_t last = batchEnd(first);
      decompress(first, last, batch);
      consume(std::span<const std::byte>(batch));
      first = last;
    }
  }

 private:
  std::uint64_t batchEnd(std::uint64_t first) const;
  void decompress(std::uint64_t first, std::uint64_t last, std::vector<std::byte>& out) const;

  Compression compression_;
  BlockHeader header_;
  std::span<const std::byte> data_;
  std::vector<std::uint64_t> blockStarts_;  // offset of each block in data_
  std::uint64_t uncompressedBytes_ = 0;
};

}  // namespace amrstream::output
