#pragma once
// The text of AMReX plotfile headers (Header, Cell_H, FAB header lines): a cursor over their
// whitespace-separated numbers, words and punctuation, and the boxes they describe. Every error
// names the file and the byte position. Used only by the AMReX reader.

#include <cstdint>
#include <glm/glm.hpp>
#include <string>

namespace amrstream::formats::amrex {

// Box corners are read within +-kMaxBoxCoordinate; a box is refused unless it lies in its level's
// domain, which spans fewer than 2^kMaxExtentBits cells, so box arithmetic fits in 64 bits.
inline constexpr long long kMaxBoxCoordinate = 1LL << 30;

class Cursor {
 public:
  // `base`: the file offset of the text's first byte, for the positions in errors.
  Cursor(std::string text, std::string source, long long base = 0)
      : text_(std::move(text)), source_(std::move(source)), base_(base) {}

  [[noreturn]] void fail(const std::string& problem) const;
  void skipSpace();
  bool atEnd();
  void expect(char c, const char* what);
  bool accept(char c);
  std::string word(const char* what);
  std::string line(const char* what);
  long long integer(const char* what);
  int smallInt(const char* what, long long low, long long high);
  double real(const char* what);  // finite
  // (a,b,c), each within +-kMaxBoxCoordinate; with `axes` 2, (a,b) and z = 0.
  glm::ivec3 intVector(const char* what, int axes = 3);

 private:
  std::string text_;
  std::string source_;
  long long base_ = 0;
  std::size_t pos_ = 0;
};

struct Box {
  glm::ivec3 lo{0}, hi{0};  // inclusive, in the level's index space
  glm::i64vec3 size() const { return glm::i64vec3(hi) - glm::i64vec3(lo) + std::int64_t{1}; }
  bool contains(const Box& inner) const {
    return glm::all(glm::lessThanEqual(lo, inner.lo)) && glm::all(glm::lessThanEqual(inner.hi, hi));
  }
  bool operator==(const Box&) const = default;
};

// The number of cells of `box`; throws InputError(source, ...) when it does not fit in 64 bits.
std::uint64_t cellCount(const Box& box, const std::string& source);

std::string boxText(const Box& box);  // "(lo.x,lo.y,lo.z)-(hi.x,hi.y,hi.z)"

// ((lo) (hi) (type)), cell-centred, not empty; with `axes` 2, a 2D box, held as one cell in z.
Box readBox(Cursor& in, const char* what, int axes = 3);

}  // namespace amrstream::formats::amrex
