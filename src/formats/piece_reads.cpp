#include "formats/piece_reads.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <vector>

#include "amrstream/error.hpp"

namespace amrstream::formats {

namespace {

// Pieces of reads straight into memory: large enough that a read's cost is the copy.
constexpr std::uint64_t kPieceBytes = std::uint64_t(8) << 20;

class ReadOnlyFile {
 public:
  ReadOnlyFile(const std::filesystem::path& path, const std::string& what)
      : path_(path), what_(what), fd_(::open(path.c_str(), O_RDONLY | O_CLOEXEC)) {
    if (fd_ < 0)
      throw InputError(path.string(),
                       fmt::format("cannot open {}: {}", what, std::strerror(errno)));
  }
  ~ReadOnlyFile() { ::close(fd_); }
  ReadOnlyFile(const ReadOnlyFile&) = delete;
  ReadOnlyFile& operator=(const ReadOnlyFile&) = delete;

  void readExactly(std::uint64_t offset, char* into, std::uint64_t count) const {
    std::uint64_t got = 0;
    while (got < count) {
      const ssize_t n = ::pread(fd_, into + got, count - got, off_t(offset + got));
      if (n < 0 && errno == EINTR) continue;
      if (n < 0)
        throw InputError(path_.string(), fmt::format("{}: reading {} bytes from byte {} failed: {}",
                                                     what_, count, offset, std::strerror(errno)));
      if (n == 0)
        throw InputError(path_.string(),
                         fmt::format("{}: read {} of {} bytes from byte {}; the file is shorter "
                                     "than it was a moment ago (changed while being read?)",
                                     what_, got, count, offset));
      got += std::uint64_t(n);
    }
  }

 private:
  std::filesystem::path path_;
  std::string what_;
  int fd_;
};

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
