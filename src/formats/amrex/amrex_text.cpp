#include "formats/amrex/amrex_text.hpp"

#include <fmt/format.h>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>

#include "amrstream/error.hpp"
#include "util/input_file.hpp"

namespace amrstream::formats::amrex {

void Cursor::fail(const std::string& problem) const {
  throw InputError(source_, fmt::format("{} (at byte {})", problem, base_ + pos_));
}

void Cursor::skipSpace() {
  while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
}

bool Cursor::atEnd() {
  skipSpace();
  return pos_ >= text_.size();
}

void Cursor::expect(char c, const char* what) {
  skipSpace();
  if (pos_ >= text_.size() || text_[pos_] != c) fail(fmt::format("expected '{}' {}", c, what));
  ++pos_;
}

bool Cursor::accept(char c) {
  skipSpace();
  if (pos_ < text_.size() && text_[pos_] == c) return ++pos_, true;
  return false;
}

std::string Cursor::word(const char* what) {
  skipSpace();
  const std::size_t start = pos_;
  while (pos_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  if (start == pos_) fail(fmt::format("expected {}", what));
  return text_.substr(start, pos_ - start);
}

std::string Cursor::line(const char* what) {
  skipSpace();
  const std::size_t end = std::min(text_.find('\n', pos_), text_.size());
  std::string result = text_.substr(pos_, end - pos_);
  while (!result.empty() && std::isspace(static_cast<unsigned char>(result.back())))
    result.pop_back();
  if (result.empty()) fail(fmt::format("expected {}", what));
  pos_ = end;
  return result;
}

long long Cursor::integer(const char* what) {
  skipSpace();
  const char* begin = text_.c_str() + pos_;
  char* end = nullptr;
  errno = 0;
  const long long value = std::strtoll(begin, &end, 10);
  if (end == begin || errno != 0) fail(fmt::format("expected an integer {}", what));
  pos_ += static_cast<std::size_t>(end - begin);
  return value;
}

int Cursor::smallInt(const char* what, long long low, long long high) {
  const long long value = integer(what);
  if (value < low || value > high)
    fail(fmt::format("{} = {} is outside [{}, {}]", what, value, low, high));
  return static_cast<int>(value);
}

double Cursor::real(const char* what) {
  skipSpace();
  const char* begin = text_.c_str() + pos_;
  char* end = nullptr;
  const double value = std::strtod(begin, &end);
  if (end == begin || !std::isfinite(value)) fail(fmt::format("expected a number {}", what));
  pos_ += static_cast<std::size_t>(end - begin);
  return value;
}

glm::ivec3 Cursor::intVector(const char* what, int axes) {
  glm::ivec3 v(0);
  const std::string where = fmt::format("in {}", what);
  expect('(', where.c_str());
  for (int axis = 0; axis < axes; ++axis) {
    if (axis > 0) expect(',', where.c_str());
    v[axis] = smallInt(where.c_str(), -kMaxBoxCoordinate, kMaxBoxCoordinate);
  }
  expect(')', where.c_str());
  return v;
}

std::uint64_t cellCount(const Box& box, const std::string& source) {
  const glm::i64vec3 size = box.size();
  const std::string what = "the cell count of box " + boxText(box);
  return checkedProduct(checkedProduct(std::uint64_t(size.x), std::uint64_t(size.y), source, what),
                        std::uint64_t(size.z), source, what);
}

std::string boxText(const Box& box) {
  return fmt::format("({},{},{})-({},{},{})", box.lo.x, box.lo.y, box.lo.z, box.hi.x, box.hi.y,
                     box.hi.z);
}

Box readBox(Cursor& in, const char* what, int axes) {
  Box box;
  const std::string where = fmt::format("in {}", what);
  in.expect('(', where.c_str());
  box.lo = in.intVector(what, axes);
  box.hi = in.intVector(what, axes);
  const glm::ivec3 type = in.intVector(what, axes);
  in.expect(')', where.c_str());
  if (type != glm::ivec3(0))
    in.fail(fmt::format("{} is not cell-centred (index type ({},{},{}))", what, type.x, type.y,
                        type.z));
  if (glm::any(glm::lessThan(box.hi, box.lo))) in.fail(fmt::format("{} is empty", what));
  return box;
}

}  // namespace amrstream::formats::amrex
