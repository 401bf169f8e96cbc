#include "output/vtk_compression.hpp"

#include <gtest/gtest.h>
#include <lz4.h>
#include <zlib.h>

#include <cmath>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "output/block_compressing_sink.hpp"
#include "output/buffered_writer.hpp"

namespace amrstream::testing {
namespace {

using output::BlockHeader;
using output::Compression;

// Collects what a BufferedWriter sends, in memory.
class MemorySink final : public output::ByteSink {
 public:
  void write(std::span<const std::byte> bytes) override {
    bytes_.insert(bytes_.end(), bytes.begin(), bytes.end());
  }
  std::vector<std::byte> bytes_;
};

std::vector<std::byte> randomBytes(std::size_t size, unsigned seed) {
  std::mt19937 random(seed);
  std::vector<std::byte> bytes(size);
  for (std::byte& b : bytes) b = std::byte(random() & 0xFF);
  return bytes;
}

// Float32 positions along a smooth curve, like a streamline's: compressible, but not trivially.
std::vector<std::byte> curveBytes(std::size_t size) {
  std::vector<std::byte> bytes(size);
  for (std::size_t i = 0; i < size / 4; ++i) {
    const float value = static_cast<float>(std::sin(0.001 * double(i)) * 100.0 + double(i % 3));
    std::memcpy(bytes.data() + 4 * i, &value, 4);
  }
  return bytes;  // a trailing partial value stays zero
}

// Inflates one block with the library itself, independently of BlockReader.
std::vector<std::byte> inflatedByLibrary(Compression compression, std::span<const std::byte> in,
                                         std::size_t size) {
  std::vector<std::byte> out(size);
  if (compression == Compression::ZLib) {
    uLongf length = size;
    EXPECT_EQ(uncompress(reinterpret_cast<Bytef*>(out.data()), &length,
                         reinterpret_cast<const Bytef*>(in.data()), in.size()),
              Z_OK);
    EXPECT_EQ(length, size);
  } else {
    EXPECT_EQ(LZ4_decompress_safe(reinterpret_cast<const char*>(in.data()),
                                  reinterpret_cast<char*>(out.data()), int(in.size()), int(size)),
              int(size));
  }
  return out;
}

struct Compressed {
  std::vector<std::byte> blocks;
  std::vector<std::uint64_t> sizes;
};

// Streams `input` through a BlockCompressingSink in writes of `chunk` bytes.
Compressed compressStreaming(Compression compression, const std::vector<std::byte>& input,
                             std::size_t chunk) {
  MemorySink file;
  output::BufferedWriter out(file);
  Compressed result;
  {
    output::BlockCompressingSink compressor(compression, out);
    output::BufferedWriter values(compressor);
    for (std::size_t at = 0; at < input.size(); at += chunk) {
      values.write(std::span(input).subspan(at, std::min(chunk, input.size() - at)));
    }
    values.flush();
    result.sizes = compressor.finish();
  }
  out.flush();
  result.blocks = std::move(file.bytes_);
  return result;
}

class CompressionRoundTrip : public ::testing::TestWithParam<Compression> {};

TEST_P(CompressionRoundTrip, RandomAndStructuredDataOfEverySize) {
  const Compression compression = GetParam();
  const std::size_t block = output::kBlockBytes;
  // 0 and 1 byte, one block exactly and one more byte, and more blocks than a batch holds.
  const std::size_t sizes[] = {
      0,         1,         block,
      block + 1, 5 * block, output::BlockCompressingSink::kBatchBytes + 3 * block + 17};
  for (const std::size_t size : sizes) {
    for (const bool random : {true, false}) {
      SCOPED_TRACE(::testing::Message() << size << " bytes, " << (random ? "random" : "curve"));
      const std::vector<std::byte> input = random ? randomBytes(size, 7) : curveBytes(size);
      for (const std::size_t chunk : {std::size_t(1) << 20, std::size_t(4093)}) {
        const Compressed compressed = compressStreaming(compression, input, chunk);

        // VTK's layout: blocks of 32768, the last one's size only when partial.
        BlockHeader header = BlockHeader::forBytes(size);
        EXPECT_EQ(header.blockCount, (size + block - 1) / block);
        EXPECT_EQ(header.blockBytes, block);
        EXPECT_EQ(header.lastBlockBytes, size % block);
        ASSERT_EQ(compressed.sizes.size(), header.blockCount);
        header.compressedSizes = compressed.sizes;
        EXPECT_EQ(header.compressedBytes(), compressed.blocks.size());
        EXPECT_EQ(header.uncompressedBytes(), size);

        // Each block inflates, by the library alone, to its slice of the input.
        std::size_t at = 0;
        for (std::uint64_t b = 0; b < header.blockCount; ++b) {
          const std::size_t length = header.uncompressedBytesOf(b);
          const auto inflated = inflatedByLibrary(
              compression, std::span(compressed.blocks).subspan(at, compressed.sizes[b]), length);
          ASSERT_TRUE(std::equal(inflated.begin(), inflated.end(), input.begin() + b * block))
              << "block " << b;
          at += compressed.sizes[b];
        }

        // And BlockReader gives the input back.
        const output::BlockReader reader(compression, header, compressed.blocks);
        EXPECT_EQ(reader.uncompressedBytes(), size);
        std::vector<std::byte> read;
        reader.forEachBatch([&](std::span<const std::byte> batch) {
          read.insert(read.end(), batch.begin(), batch.end());
        });
        EXPECT_TRUE(read == input);
      }
    }
  }
}

// Point ids, as in a polyline's connectivity: both compressors shrink them (LZ4 does not shrink
// float positions: their low mantissa bits look random to it).
TEST_P(CompressionRoundTrip, CompressesConnectivity) {
  std::vector<std::int64_t> ids(64 * output::kBlockBytes / 8);
  for (std::size_t i = 0; i < ids.size(); ++i) ids[i] = std::int64_t(i);
  const output::CompressedBlocks compressed =
      output::compressBlocks(GetParam(), std::as_bytes(std::span(ids)));
  EXPECT_LT(compressed.bytes.size(), ids.size() * 8 * 3 / 4);
}

// The bounds the reader enforces before allocating must admit every real stream: the most
// compressible block (zeros) at the strongest zlib level stays within them.
TEST_P(CompressionRoundTrip, TheInflationBoundHoldsForTheMostCompressibleBlock) {
  const std::vector<std::byte> zeros(output::kBlockBytes);
  const output::CompressedBlocks compressed = output::compressBlocks(GetParam(), zeros, {9});
  ASSERT_EQ(compressed.sizes.size(), 1u);
  EXPECT_LE(zeros.size(), compressed.sizes[0] * output::maxInflationRatio(GetParam()));
}

TEST_P(CompressionRoundTrip, ReaderRefusesBeforeAllocatingWhatNoStreamCouldHold) {
  const std::vector<std::byte> input = curveBytes(3 * output::kBlockBytes);
  const output::CompressedBlocks compressed = output::compressBlocks(GetParam(), input);
  BlockHeader header = BlockHeader::forBytes(input.size());
  header.compressedSizes = compressed.sizes;

  BlockHeader huge = header;
  huge.blockBytes = std::uint64_t(1) << 50;
  EXPECT_THROW(output::BlockReader(GetParam(), huge, compressed.bytes),
               output::CompressedDataError);
  // Blocks past the end of the data.
  EXPECT_THROW(output::BlockReader(GetParam(), header,
                                   std::span(compressed.bytes).first(compressed.bytes.size() - 1)),
               output::CompressedDataError);
  BlockHeader emptyBlock = header;
  emptyBlock.compressedSizes[1] = 0;
  EXPECT_THROW(output::BlockReader(GetParam(), emptyBlock, compressed.bytes),
               output::CompressedDataError);
}

TEST_P(CompressionRoundTrip, ReaderNamesTheCorruptBlock) {
  const std::vector<std::byte> input = randomBytes(3 * output::kBlockBytes, 3);
  output::CompressedBlocks compressed = output::compressBlocks(GetParam(), input);
  BlockHeader header = BlockHeader::forBytes(input.size());
  header.compressedSizes = compressed.sizes;
  // Block 2 claims 10 bytes less than it inflates to, and the total says the same.
  header.lastBlockBytes = output::kBlockBytes - 10;
  const output::BlockReader reader(GetParam(), header, compressed.bytes);
  try {
    reader.forEachBatch([](std::span<const std::byte>) {});
    FAIL() << "no error";
  } catch (const output::CompressedDataError& error) {
    EXPECT_NE(std::string(error.what()).find("block 2 is not a valid"), std::string::npos)
        << error.what();
  }
}

INSTANTIATE_TEST_SUITE_P(BlockCompressors, CompressionRoundTrip,
                         ::testing::Values(Compression::ZLib, Compression::LZ4),
                         [](const auto& info) {
                           return std::string(output::compressionName(info.param));
                         });

TEST(CompressionNames, MatchTheCliAndVtk) {
  for (const Compression c : {Compression::None, Compression::ZLib, Compression::LZ4}) {
    EXPECT_EQ(output::compressionNamed(output::compressionName(c)), c);
  }
  EXPECT_EQ(output::compressionName(Compression::ZLib), "zlib");
  EXPECT_EQ(output::compressionName(Compression::LZ4), "lz4");
  EXPECT_EQ(output::compressionName(Compression::None), "none");
  EXPECT_EQ(output::compressionNamed("gzip"), std::nullopt);
  EXPECT_EQ(output::vtkCompressorName(Compression::ZLib), "vtkZLibDataCompressor");
  EXPECT_EQ(output::vtkCompressorName(Compression::LZ4), "vtkLZ4DataCompressor");
  EXPECT_EQ(output::vtkCompressorName(Compression::None), "");
  EXPECT_EQ(output::compressionOfVtkCompressor("vtkLZ4DataCompressor"), Compression::LZ4);
  EXPECT_EQ(output::compressionOfVtkCompressor("vtkLZMADataCompressor"), std::nullopt);
  EXPECT_EQ(output::compressionOfVtkCompressor(""), std::nullopt);
}

}  // namespace
}  // namespace amrstream::testing
