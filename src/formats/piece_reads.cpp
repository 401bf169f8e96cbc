#include "formats/piece_reads.hpp"

#include <fmt/format.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <vector>

#include "formats/read_only_file.hpp"

namespace amrstream::formats {

namespace {

// Pieces of reads straight into memory: large enough that a read's cost is the copy.
constexpr std::uint64_t kPieceBytes = std::uint64_t(8) << 20;

}  // namespace

void readInPieces(const std::filesystem::path& path, std::uint64_t offset, char* into,
                  std::uint64_t count, const std::string& what) {
  const ReadOnlyFile file(path, what);
  const std::uint64_t pieces = (count + kPieceBytes - 1) / kPieceBytes;
  tbb::parallel_for(std::uint64_t(0), pieces, [&](std::uint64_t p) {
    const std::uint64_t first = p * kPieceBytes;
    file.readExactly(offset + first, into + first, std::min(kPieceBytes, count - first));
  });
}

void forEachPiece(
    const std::filesystem::path& path, std::uint64_t offset, std::uint64_t count,
    std::uint64_t pieceBytes, const std::string& what,
    const std::function<void(std::uint64_t first, std::span<const char> bytes)>& use) {
  const ReadOnlyFile file(path, what);
  tbb::enumerable_thread_specific<std::vector<char>> buffers;
  const std::uint64_t pieces = (count + pieceBytes - 1) / pieceBytes;
  tbb::parallel_for(std::uint64_t(0), pieces, [&](std::uint64_t p) {
    const std::uint64_t first = p * pieceBytes;
    const std::uint64_t bytes = std::min(pieceBytes, count - first);
    std::vector<char>& buffer = buffers.local();
    buffer.resize(pieceBytes);
    file.readExactly(offset + first, buffer.data(), bytes);
    use(first, {buffer.data(), bytes});
  });
}

}  // namespace amrstream::formats
