#include "formats/float_runs.hpp"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <mutex>
#include <vector>

#include "formats/cell_checks.hpp"
#include "formats/read_only_file.hpp"

namespace amrstream::formats {

namespace {

// Values per piece: a few MiB, so that every core has pieces and each read's cost is the copy.
constexpr std::uint64_t kPieceValues = std::uint64_t(1) << 20;

struct Piece {
  std::size_t run;
  std::uint64_t first, count;
};

std::vector<Piece> piecesOf(std::span<const FloatRun> runs) {
  std::vector<Piece> pieces;
  for (std::size_t r = 0; r < runs.size(); ++r)
    for (std::uint64_t first = 0; first < runs[r].count; first += kPieceValues)
      pieces.push_back({r, first, std::min(kPieceValues, runs[r].count - first)});
  return pieces;
}

// The first unusable value among `values` (those of the piece), if any.
template <typename T>
std::optional<UnusableValue> firstUnusable(const T* values, const Piece& piece) {
  for (std::uint64_t i = 0; i < piece.count; ++i) {
    const double value = double(values[i]);
    if (std::abs(value) <= kLargestFieldValue) continue;  // the usual case, NaN excluded
    if (auto problem = unusableFieldValue(value))
      return UnusableValue{piece.run, piece.first + i, value, std::move(*problem)};
  }
  return std::nullopt;
}

// The unusable value that comes first, of those the threads met.
class FirstUnusable {
 public:
  void offer(UnusableValue candidate) {
    const std::lock_guard lock(mutex_);
    if (!first_ ||
        std::pair(candidate.run, candidate.index) < std::pair(first_->run, first_->index))
      first_ = std::move(candidate);
  }
  std::optional<UnusableValue> take() { return std::move(first_); }

 private:
  std::mutex mutex_;
  std::optional<UnusableValue> first_;
};

// The bytes of each of `count` values of `T` reversed, in place.
template <typename T>
void swapBytes(T* values, std::uint64_t count) {
  for (std::uint64_t i = 0; i < count; ++i) {
    if constexpr (sizeof(T) == 4) {
      std::uint32_t bits;
      std::memcpy(&bits, values + i, 4);
      bits = __builtin_bswap32(bits);
      std::memcpy(values + i, &bits, 4);
    } else {
      std::uint64_t bits;
      std::memcpy(&bits, values + i, 8);
      bits = __builtin_bswap64(bits);
      std::memcpy(values + i, &bits, 8);
    }
  }
}

}  // namespace

std::optional<UnusableValue> readFloatRuns(const std::filesystem::path& path,
                                           FloatEncoding encoding, std::span<const FloatRun> runs,
                                           const std::string& what) {
  const ReadOnlyFile file(path, what);
  const std::vector<Piece> pieces = piecesOf(runs);
  tbb::enumerable_thread_specific<std::vector<double>> doubles;
  FirstUnusable unusable;
  tbb::parallel_for(std::size_t(0), pieces.size(), [&](std::size_t p) {
    const Piece& piece = pieces[p];
    const FloatRun& run = runs[piece.run];
    const std::uint64_t offset = run.offset + piece.first * std::uint64_t(encoding.bytes);
    float* into = run.into + piece.first;
    std::optional<UnusableValue> found;
    if (encoding.bytes == 4) {
      file.readExactly(offset, reinterpret_cast<char*>(into), piece.count * 4);
      if (encoding.bigEndian) swapBytes(into, piece.count);
      found = firstUnusable(into, piece);
    } else {
      std::vector<double>& buffer = doubles.local();
      buffer.resize(piece.count);
      file.readExactly(offset, reinterpret_cast<char*>(buffer.data()), piece.count * 8);
      if (encoding.bigEndian) swapBytes(buffer.data(), piece.count);
      found = firstUnusable(buffer.data(), piece);
      std::transform(buffer.begin(), buffer.end(), into, [](double v) { return float(v); });
    }
    if (found) unusable.offer(std::move(*found));
  });
  return unusable.take();
}

}  // namespace amrstream::formats
