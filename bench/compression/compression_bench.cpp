// Throughput and size of the .vtp compressors on streamline-like data, to choose the zlib level:
//
//   amrstream_compression_bench [MEGABYTES] [THREADS,...]     (default 200 MB, 1 and all threads)
//
// Two inputs of MEGABYTES each: Float32 positions of smooth random curves (as traces are), and
// Int64 point ids 0, 1, 2, ... (as a polyline's connectivity). For each compressor and level of
// the zlib format (written by libdeflate), and each thread count: the
// input streamed through BlockCompressingSink (1 MiB writes, as the .vtp writer's producers make
// them; compressed bytes discarded), the best of 3 runs. Prints MB/s of raw input (1 MB = 10^6
// bytes) and the compressed size in % of the raw size. A benchmark, not a test: nothing is
// asserted.

#include <fmt/format.h>
#include <tbb/global_control.h>
#include <tbb/info.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <random>
#include <span>
#include <sstream>
#include <string>
#include <vector>

#include "output/block_compressing_sink.hpp"
#include "output/buffered_writer.hpp"
#include "output/vtk_compression.hpp"

namespace {

using amrstream::output::BlockCompressingSink;
using amrstream::output::BufferedWriter;
using amrstream::output::Compression;

class CountingSink final : public amrstream::output::ByteSink {
 public:
  void write(std::span<const std::byte> bytes) override { bytes_ += bytes.size(); }
  std::uint64_t bytes_ = 0;
};

// Curves of 1000 points with a slowly turning direction and step, in a box of about 100 units.
std::vector<float> curvePositions(std::size_t floats) {
  std::mt19937 random(1);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  std::vector<float> out;
  out.reserve(floats);
  while (out.size() + 3 <= floats) {
    float p[3] = {50 + 40 * unit(random), 50 + 40 * unit(random), 50 + 40 * unit(random)};
    float d[3] = {unit(random), unit(random), unit(random)};
    for (int point = 0; point < 1000 && out.size() + 3 <= floats; ++point) {
      const float step = 0.05f * (1.5f + std::sin(0.01f * float(point)));
      for (int k = 0; k < 3; ++k) {
        d[k] += 0.05f * unit(random);
        p[k] += step * d[k];
        out.push_back(p[k]);
      }
    }
  }
  out.resize(floats, 0.0f);
  return out;
}

struct Result {
  double megabytesPerSecond = 0;
  double percent = 0;
};

Result streamed(Compression compression, amrstream::output::ZLibSettings zlib,
                std::span<const std::byte> input) {
  Result best;
  for (int run = 0; run < 3; ++run) {
    CountingSink file;
    BufferedWriter out(file);
    const auto start = std::chrono::steady_clock::now();
    {
      BlockCompressingSink compressor(compression, out, zlib);
      BufferedWriter values(compressor);
      for (std::size_t at = 0; at < input.size(); at += 1 << 20) {
        values.write(input.subspan(at, std::min<std::size_t>(1 << 20, input.size() - at)));
      }
      values.flush();
      compressor.finish();
    }
    out.flush();
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    best.megabytesPerSecond =
        std::max(best.megabytesPerSecond, double(input.size()) / seconds / 1e6);
    best.percent = 100.0 * double(file.bytes_) / double(input.size());
  }
  return best;
}

std::vector<int> threadCounts(const char* text) {
  std::vector<int> counts;
  std::stringstream list(text);
  for (std::string item; std::getline(list, item, ',');) counts.push_back(std::atoi(item.c_str()));
  return counts;
}

}  // namespace

int main(int argc, char** argv) {
  const std::size_t megabytes = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 200;
  const int cores = tbb::info::default_concurrency();
  const std::vector<int> threads = argc > 2 ? threadCounts(argv[2]) : std::vector<int>{1, cores};
  const std::size_t bytes = megabytes * 1000 * 1000;

  const std::vector<float> positions = curvePositions(bytes / sizeof(float));
  std::vector<std::int64_t> ids(bytes / sizeof(std::int64_t));
  for (std::size_t i = 0; i < ids.size(); ++i) ids[i] = std::int64_t(i);
  const struct {
    const char* name;
    std::span<const std::byte> bytes;
  } inputs[] = {{"Float32 positions", std::as_bytes(std::span(positions))},
                {"Int64 connectivity", std::as_bytes(std::span(ids))}};
  const struct {
    Compression compression;
    amrstream::output::ZLibSettings zlib;
    const char* name;
  } codecs[] = {{Compression::ZLib, {1}, "zlib 1"},
                {Compression::ZLib, {2}, "zlib 2"},
                {Compression::ZLib, {5}, "zlib 5"},
                {Compression::ZLib, {6}, "zlib 6"},
                {Compression::LZ4, {}, "lz4"}};

  fmt::print("{} MB per input, {} hardware threads; MB/s of raw input, size in % of raw\n",
             megabytes, cores);
  for (const auto& input : inputs) {
    fmt::print("\n{}\n{:<14}", input.name, "");
    for (const int n : threads) fmt::print("{:>12}", fmt::format("{} thr MB/s", n));
    fmt::print("{:>9}\n", "size %");
    for (const auto& codec : codecs) {
      fmt::print("{:<14}", codec.name);
      Result result;
      for (const int n : threads) {
        const tbb::global_control limit(tbb::global_control::max_allowed_parallelism,
                                        std::size_t(n));
        result = streamed(codec.compression, codec.zlib, input.bytes);
        fmt::print("{:>12.0f}", result.megabytesPerSecond);
        std::fflush(stdout);
      }
      fmt::print("{:>9.1f}\n", result.percent);
    }
  }
  return 0;
}
