#include "output/vtk_compression.hpp"

#include <fmt/format.h>
#include <libdeflate.h>
#include <lz4.h>
#include <tbb/parallel_for.h>
#include <zlib.h>

#include <algorithm>
#include <climits>
#include <cstring>
#include <limits>
#include <memory>
#include <utility>

namespace amrstream::output {
namespace {

struct Names {
  Compression compression;
  std::string_view name;
  std::string_view vtkClass;
};
constexpr Names kNames[] = {{Compression::None, "none", ""},
                            {Compression::ZLib, "zlib", "vtkZLibDataCompressor"},
                            {Compression::LZ4, "lz4", "vtkLZ4DataCompressor"}};

const Names& namesOf(Compression compression) {
  for (const Names& names : kNames) {
    if (names.compression == compression) return names;
  }
  throw std::logic_error("unknown Compression");
}

// Blocks decompressed together when reading; a batch holds at most this many bytes unless one
// block is larger.
constexpr std::uint64_t kReadBatchBytes = 256 * kBlockBytes;

// libdeflate writes the zlib format (what vtkZLibDataCompressor reads with zlib) two to three
// times faster than zlib itself at the same ratio on float data; a compressor is made once per
// thread and level, since setting one up costs more than compressing a block.
libdeflate_compressor& deflaterFor(int level) {
  struct Owned {
    int level;
    std::unique_ptr<libdeflate_compressor, decltype(&libdeflate_free_compressor)> compressor;
  };
  thread_local std::vector<Owned> compressors;
  for (Owned& owned : compressors)
    if (owned.level == level) return *owned.compressor;
  libdeflate_compressor* made = libdeflate_alloc_compressor(level);
  if (!made) throw std::runtime_error(fmt::format("libdeflate: no compressor of level {}", level));
  compressors.push_back({level, {made, &libdeflate_free_compressor}});
  return *made;
}

std::size_t deflateBlock(std::span<const std::byte> in, std::span<std::byte> out,
                         ZLibSettings settings) {
  const std::size_t size = libdeflate_zlib_compress(&deflaterFor(settings.level), in.data(),
                                                    in.size(), out.data(), out.size());
  // The slot holds libdeflate_zlib_compress_bound() bytes, so 0 (did not fit) cannot happen.
  if (size == 0) throw std::runtime_error("libdeflate: a block did not fit its bound");
  return size;
}

// True when `in` is a valid stream that inflates to exactly out.size() bytes.
bool decompressBlock(Compression compression, std::span<const std::byte> in,
                     std::span<std::byte> out) {
  if (compression == Compression::ZLib) {
    uLongf size = out.size();
    uLong consumed = in.size();
    // A zero-size output needs a valid pointer all the same.
    Bytef empty = 0;
    Bytef* target = out.empty() ? &empty : reinterpret_cast<Bytef*>(out.data());
    const int status =
        uncompress2(target, &size, reinterpret_cast<const Bytef*>(in.data()), &consumed);
    return status == Z_OK && size == out.size();
  }
  if (compression == Compression::LZ4) {
    // Sizes were checked against the ratio bound, which keeps both within int for real blocks.
    if (in.size() > INT_MAX || out.size() > INT_MAX) return false;
    const int size = LZ4_decompress_safe(reinterpret_cast<const char*>(in.data()),
                                         reinterpret_cast<char*>(out.data()),
                                         static_cast<int>(in.size()), static_cast<int>(out.size()));
    return size >= 0 && static_cast<std::size_t>(size) == out.size();
  }
  throw std::logic_error("decompressBlock without a compressor");
}

}  // namespace

std::size_t compressBlock(Compression compression, std::span<const std::byte> in,
                          std::span<std::byte> out, ZLibSettings zlib) {
  if (compression == Compression::ZLib) return deflateBlock(in, out, zlib);
  if (compression == Compression::LZ4) {
    const int size = LZ4_compress_default(
        reinterpret_cast<const char*>(in.data()), reinterpret_cast<char*>(out.data()),
        static_cast<int>(in.size()), static_cast<int>(out.size()));
    if (size <= 0) throw std::runtime_error("LZ4_compress_default failed");
    return static_cast<std::size_t>(size);
  }
  throw std::logic_error("compressBlock without a compressor");
}

std::optional<Compression> compressionNamed(std::string_view name) {
  for (const Names& names : kNames) {
    if (names.name == name) return names.compression;
  }
  return std::nullopt;
}

std::string_view compressionName(Compression compression) { return namesOf(compression).name; }

std::string_view vtkCompressorName(Compression compression) {
  return namesOf(compression).vtkClass;
}

std::optional<Compression> compressionOfVtkCompressor(std::string_view className) {
  for (const Names& names : kNames) {
    if (!names.vtkClass.empty() && names.vtkClass == className) return names.compression;
  }
  return std::nullopt;
}

std::uint64_t maxInflationRatio(Compression compression) {
  switch (compression) {
    case Compression::ZLib:
      return 1032;
    case Compression::LZ4:
      return 255;
    case Compression::None:
      break;
  }
  return 1;
}

BlockHeader BlockHeader::forBytes(std::uint64_t uncompressedBytes) {
  BlockHeader header;
  header.blockCount = (uncompressedBytes + kBlockBytes - 1) / kBlockBytes;
  header.lastBlockBytes = uncompressedBytes % kBlockBytes;
  return header;
}

std::uint64_t BlockHeader::uncompressedBytesOf(std::uint64_t block) const {
  return block + 1 == blockCount && lastBlockBytes != 0 ? lastBlockBytes : blockBytes;
}

std::uint64_t BlockHeader::uncompressedBytes() const {
  if (blockCount == 0) return 0;
  const std::uint64_t full = blockCount - 1;
  const std::uint64_t last = uncompressedBytesOf(blockCount - 1);
  if (blockBytes != 0 && full > (std::numeric_limits<std::uint64_t>::max() - last) / blockBytes) {
    throw CompressedDataError(
        fmt::format("{} blocks of {} bytes overflow 64 bits", blockCount, blockBytes));
  }
  return full * blockBytes + last;
}

std::uint64_t BlockHeader::compressedBytes() const {
  std::uint64_t total = 0;
  for (const std::uint64_t size : compressedSizes) {
    if (size > std::numeric_limits<std::uint64_t>::max() - total) {
      throw CompressedDataError("the compressed block sizes overflow 64 bits");
    }
    total += size;
  }
  return total;
}

std::size_t maxCompressedBytes(Compression compression, std::size_t uncompressedBytes) {
  if (compression == Compression::ZLib)
    return libdeflate_zlib_compress_bound(&deflaterFor(ZLibSettings{}.level), uncompressedBytes);
  if (compression == Compression::LZ4) {
    return static_cast<std::size_t>(LZ4_compressBound(static_cast<int>(uncompressedBytes)));
  }
  return uncompressedBytes;
}

CompressedBlocks compressBlocks(Compression compression, std::span<const std::byte> input,
                                ZLibSettings zlib) {
  const std::size_t blockCount = (input.size() + kBlockBytes - 1) / kBlockBytes;
  const std::size_t slot = maxCompressedBytes(compression, kBlockBytes);
  // Each block compresses into its own slot of the scratch buffer; then the slots are packed.
  std::vector<std::byte> scratch(blockCount * slot);
  CompressedBlocks out;
  out.sizes.resize(blockCount);
  tbb::parallel_for(std::size_t(0), blockCount, [&](std::size_t block) {
    const std::span<const std::byte> in =
        input.subspan(block * kBlockBytes,
                      std::min<std::size_t>(kBlockBytes, input.size() - block * kBlockBytes));
    out.sizes[block] =
        compressBlock(compression, in, std::span(scratch).subspan(block * slot, slot), zlib);
  });
  std::size_t packed = 0;
  for (std::size_t block = 0; block < blockCount; ++block) {
    std::memmove(scratch.data() + packed, scratch.data() + block * slot, out.sizes[block]);
    packed += out.sizes[block];
  }
  scratch.resize(packed);
  out.bytes = std::move(scratch);
  return out;
}

BlockReader::BlockReader(Compression compression, BlockHeader header,
                         std::span<const std::byte> data)
    : compression_(compression), header_(std::move(header)), data_(data) {
  if (compression_ == Compression::None) throw std::logic_error("BlockReader without compressor");
  if (header_.compressedSizes.size() != header_.blockCount) {
    throw std::logic_error("BlockReader: compressedSizes do not match blockCount");
  }
  if (header_.blockCount > 0 && header_.blockBytes == 0) {
    throw CompressedDataError(
        fmt::format("the block header declares {} blocks of 0 bytes", header_.blockCount));
  }
  if (header_.lastBlockBytes > header_.blockBytes) {
    throw CompressedDataError(fmt::format("the last block ({} bytes) is larger than a block ({})",
                                          header_.lastBlockBytes, header_.blockBytes));
  }
  uncompressedBytes_ = header_.uncompressedBytes();
  const std::uint64_t compressed = header_.compressedBytes();
  if (compressed > data_.size()) {
    throw CompressedDataError(fmt::format(
        "the compressed blocks need {} bytes, only {} are left in the file (truncated?)",
        compressed, data_.size()));
  }
  const std::uint64_t ratio = maxInflationRatio(compression_);
  blockStarts_.reserve(header_.blockCount);  // the sizes vector of that length exists already
  std::uint64_t start = 0;
  for (std::uint64_t block = 0; block < header_.blockCount; ++block) {
    const std::uint64_t in = header_.compressedSizes[block];
    const std::uint64_t out = header_.uncompressedBytesOf(block);
    if (in == 0 || out / ratio > in) {
      throw CompressedDataError(
          fmt::format("block {} claims {} bytes from {} compressed bytes, more than {} can "
                      "inflate to",
                      block, out, in, compressionName(compression_)));
    }
    blockStarts_.push_back(start);
    start += in;
  }
}

std::uint64_t BlockReader::batchEnd(std::uint64_t first) const {
  std::uint64_t last = first + 1;
  std::uint64_t bytes = header_.uncompressedBytesOf(first);
  while (last < header_.blockCount &&
         bytes + header_.uncompressedBytesOf(last) <= kReadBatchBytes) {
    bytes += header_.uncompressedBytesOf(last++);
  }
  return last;
}

void BlockReader::decompress(std::uint64_t first, std::uint64_t last,
                             std::vector<std::byte>& out) const {
  // Block sizes within a batch are each at most blockBytes, and every block but the first of the
  // batch keeps the batch under kReadBatchBytes, so these offsets are small.
  std::vector<std::size_t> outStart(last - first + 1, 0);
  for (std::uint64_t block = first; block < last; ++block) {
    outStart[block - first + 1] =
        outStart[block - first] + static_cast<std::size_t>(header_.uncompressedBytesOf(block));
  }
  out.resize(outStart.back());
  std::vector<char> failed(last - first, 0);
  tbb::parallel_for(first, last, [&](std::uint64_t block) {
    const std::size_t i = block - first;
    const std::span<const std::byte> in = data_.subspan(
        blockStarts_[block], static_cast<std::size_t>(header_.compressedSizes[block]));
    const std::span<std::byte> to =
        std::span(out).subspan(outStart[i], outStart[i + 1] - outStart[i]);
    failed[i] = decompressBlock(compression_, in, to) ? 0 : 1;
  });
  const auto bad = std::find(failed.begin(), failed.end(), 1);
  if (bad != failed.end()) {
    const std::uint64_t block = first + static_cast<std::uint64_t>(bad - failed.begin());
    throw CompressedDataError(
        fmt::format("block {} is not a valid {} stream of {} bytes (corrupt, or its size is wrong)",
                    block, compressionName(compression_), header_.uncompressedBytesOf(block)));
  }
}

}  // namespace amrstream::output
