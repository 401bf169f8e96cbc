#include "amrex_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "amrex_info.hpp"
#include "util/input_error.hpp"

namespace amrstream::formats {
namespace {

namespace fs = std::filesystem;

// Reads the whitespace-separated numbers, words and punctuation of AMReX text headers.
class Cursor {
 public:
  // `base`: the file offset of the text's first byte, for the positions in errors.
  Cursor(std::string text, std::string source, long long base = 0)
      : text_(std::move(text)), source_(std::move(source)), base_(base) {}

  [[noreturn]] void fail(const std::string& problem) const {
    throw InputError(source_, fmt::format("{} (at byte {})", problem, base_ + pos_));
  }
  void skipSpace() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  }
  bool atEnd() {
    skipSpace();
    return pos_ >= text_.size();
  }
  void expect(char c, const char* what) {
    skipSpace();
    if (pos_ >= text_.size() || text_[pos_] != c) fail(fmt::format("expected '{}' {}", c, what));
    ++pos_;
  }
  bool accept(char c) {
    skipSpace();
    if (pos_ < text_.size() && text_[pos_] == c) return ++pos_, true;
    return false;
  }
  std::string word(const char* what) {
    skipSpace();
    const std::size_t start = pos_;
    while (pos_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
    if (start == pos_) fail(fmt::format("expected {}", what));
    return text_.substr(start, pos_ - start);
  }
  std::string line(const char* what) {
    skipSpace();
    const std::size_t end = std::min(text_.find('\n', pos_), text_.size());
    std::string result = text_.substr(pos_, end - pos_);
    while (!result.empty() && std::isspace(static_cast<unsigned char>(result.back())))
      result.pop_back();
    if (result.empty()) fail(fmt::format("expected {}", what));
    pos_ = end;
    return result;
  }
  long long integer(const char* what) {
    skipSpace();
    const char* begin = text_.c_str() + pos_;
    char* end = nullptr;
    errno = 0;
    const long long value = std::strtoll(begin, &end, 10);
    if (end == begin || errno != 0) fail(fmt::format("expected an integer {}", what));
    pos_ += static_cast<std::size_t>(end - begin);
    return value;
  }
  int smallInt(const char* what, long long low, long long high) {
    const long long value = integer(what);
    if (value < low || value > high)
      fail(fmt::format("{} = {} is outside [{}, {}]", what, value, low, high));
    return static_cast<int>(value);
  }
  double real(const char* what) {
    skipSpace();
    const char* begin = text_.c_str() + pos_;
    char* end = nullptr;
    const double value = std::strtod(begin, &end);
    if (end == begin || !std::isfinite(value)) fail(fmt::format("expected a number {}", what));
    pos_ += static_cast<std::size_t>(end - begin);
    return value;
  }
  glm::ivec3 intVector(const char* what) {  // (a,b,c)
    glm::ivec3 v;
    const std::string where = fmt::format("in {}", what);
    expect('(', where.c_str());
    for (int axis = 0; axis < 3; ++axis) {
      if (axis > 0) expect(',', where.c_str());
      v[axis] = smallInt(where.c_str(), -(1LL << 30), 1LL << 30);
    }
    expect(')', where.c_str());
    return v;
  }
  const std::string& source() const { return source_; }
  std::size_t position() const { return pos_; }

 private:
  std::string text_;
  std::string source_;
  long long base_ = 0;
  std::size_t pos_ = 0;
};

struct Box {
  glm::ivec3 lo{0}, hi{0};  // inclusive, in the level's index space
  glm::ivec3 size() const { return hi - lo + 1; }
  long long count() const {
    const glm::ivec3 s = size();
    return static_cast<long long>(s.x) * s.y * s.z;
  }
  bool operator==(const Box&) const = default;
};

Box readBox(Cursor& in, const char* what) {  // ((lo) (hi) (type))
  Box box;
  const std::string where = fmt::format("in {}", what);
  in.expect('(', where.c_str());
  box.lo = in.intVector(what);
  box.hi = in.intVector(what);
  const glm::ivec3 type = in.intVector(what);
  in.expect(')', where.c_str());
  if (type != glm::ivec3(0))
    in.fail(fmt::format("{} is not cell-centred (index type ({},{},{}))", what, type.x, type.y,
                        type.z));
  if (glm::any(glm::lessThan(box.hi, box.lo))) in.fail(fmt::format("{} is empty", what));
  return box;
}

std::string readText(const fs::path& path, const char* what) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string(), fmt::format("cannot open the {}", what));
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

struct PlotHeader {
  std::vector<std::string> names;
  double time = 0.0;
  int finestLevel = 0;
  glm::dvec3 probLo{0.0}, probHi{0.0};
  std::vector<int> ratios;  // level L -> L+1
  std::vector<Box> domains;
  std::vector<glm::dvec3> dx;
  std::vector<int> gridCounts;
  std::vector<std::string> levelPaths;  // e.g. Level_1/Cell
};

PlotHeader parseHeader(const fs::path& path) {
  Cursor in(readText(path, "plotfile Header"), path.string());
  PlotHeader h;
  const std::string version = in.line("the version line");
  if (version.rfind("HyperCLaw", 0) != 0)
    in.fail(fmt::format("version '{}' is not a HyperCLaw plotfile", version));
  const int ncomp = in.smallInt("the number of variables", 1, 100000);
  for (int c = 0; c < ncomp; ++c) h.names.push_back(in.line("a variable name"));
  const int dim = in.smallInt("the dimension", 1, 3);
  if (dim != 3) in.fail(fmt::format("the plotfile is {}D; amrstream reads 3D plotfiles", dim));
  h.time = in.real("(the time)");
  h.finestLevel = in.smallInt("finest_level", 0, bricks::kMaxLevel);
  const int levels = h.finestLevel + 1;
  for (int axis = 0; axis < 3; ++axis) h.probLo[axis] = in.real("in prob_lo");
  for (int axis = 0; axis < 3; ++axis) h.probHi[axis] = in.real("in prob_hi");
  if (glm::any(glm::lessThanEqual(h.probHi, h.probLo))) in.fail("prob_hi is not above prob_lo");
  for (int l = 0; l < h.finestLevel; ++l) {
    const int ratio = in.smallInt("a refinement ratio", 1, 1 << 20);
    if (!std::has_single_bit(static_cast<unsigned>(ratio)))
      in.fail(fmt::format("refinement ratio {} is not a power of two", ratio));
    h.ratios.push_back(ratio);
  }
  for (int l = 0; l < levels; ++l) h.domains.push_back(readBox(in, "a level domain box"));
  for (int l = 0; l < levels; ++l) in.integer("(a level step)");
  for (int l = 0; l < levels; ++l) {
    glm::dvec3 dx;
    for (int axis = 0; axis < 3; ++axis) dx[axis] = in.real("in a level's dx");
    h.dx.push_back(dx);
  }
  if (in.smallInt("coord_sys", 0, 2) != 0) in.fail("only Cartesian plotfiles (coord_sys 0)");
  in.integer("(bwidth)");
  for (int l = 0; l < levels; ++l) {
    if (in.integer("(the level number)") != l) in.fail(fmt::format("expected level {}", l));
    h.gridCounts.push_back(in.smallInt("a level's grid count", 1, 1 << 30));
    in.real("(the level time)");
    in.integer("(the level step)");
    for (int g = 0; g < h.gridCounts.back() * 3; ++g) {
      in.real("(a grid's lower extent)");
      in.real("(a grid's upper extent)");
    }
    h.levelPaths.push_back(in.word("the level's path (Level_N/Cell)"));
  }
  return h;
}

struct FabEntry {
  Box box;
  std::string file;
  long long offset = 0;
};

struct LevelLayout {
  int nghost = 0;
  std::vector<FabEntry> fabs;  // in box order
};

LevelLayout parseCellHeader(const fs::path& path, int ncomp, int gridCount) {
  Cursor in(readText(path, "level header (Cell_H)"), path.string());
  in.integer("(the version)");
  in.integer("(how)");
  const long long fileComps = in.integer("(ncomp)");
  if (fileComps != ncomp)
    in.fail(
        fmt::format("{} components, but the plotfile Header names {} variables", fileComps, ncomp));
  LevelLayout layout;
  layout.nghost = in.smallInt("nghost", 0, 1 << 20);
  in.expect('(', "opening the BoxArray");
  const long long boxes = in.integer("(the box count)");
  if (boxes != gridCount)
    in.fail(fmt::format("{} boxes, but the plotfile Header lists {} grids", boxes, gridCount));
  in.integer("(the BoxArray tag)");
  layout.fabs.resize(static_cast<std::size_t>(boxes));
  for (FabEntry& fab : layout.fabs) fab.box = readBox(in, "a BoxArray box");
  in.expect(')', "closing the BoxArray");
  if (in.integer("(the FAB count)") != boxes) in.fail("the FAB count differs from the box count");
  for (FabEntry& fab : layout.fabs) {
    if (in.word("'FabOnDisk:'") != "FabOnDisk:") in.fail("expected 'FabOnDisk: FILE OFFSET'");
    fab.file = in.word("a Cell_D file name");
    if (fab.file.find('/') != std::string::npos || fab.file == "..")
      in.fail(fmt::format("FAB file name '{}' is not a plain file name", fab.file));
    fab.offset = in.integer("(a FAB byte offset)");
    if (fab.offset < 0) in.fail("negative FAB byte offset");
  }
  return layout;
}

// The FAB header's real descriptor: bytes per value and byte order.
struct RealFormat {
  int bytes = 8;
  bool bigEndian = false;
};

RealFormat readRealFormat(Cursor& in) {
  // ((8, (64 11 52 0 1 12 0 1023)),(8, (8 7 6 5 4 3 2 1)))
  in.expect('(', "opening the FAB real descriptor");
  in.expect('(', "opening the FAB number format");
  const int bytes = in.smallInt("the FAB value size", 1, 64);
  in.expect(',', "in the FAB number format");
  in.expect('(', "in the FAB number format");
  std::vector<long long> format;
  while (!in.accept(')')) format.push_back(in.integer("in the FAB number format"));
  in.expect(')', "closing the FAB number format");
  const std::vector<long long> f64{64, 11, 52, 0, 1, 12, 0, 1023};
  const std::vector<long long> f32{32, 8, 23, 0, 1, 9, 0, 127};
  if (!((bytes == 8 && format == f64) || (bytes == 4 && format == f32)))
    in.fail("the FAB values are neither IEEE float64 nor float32");
  in.expect(',', "in the FAB real descriptor");
  in.expect('(', "opening the FAB byte order");
  if (in.integer("(the byte order size)") != bytes) in.fail("byte order size differs");
  in.expect(',', "in the FAB byte order");
  in.expect('(', "in the FAB byte order");
  std::vector<long long> order;
  while (!in.accept(')')) order.push_back(in.integer("in the FAB byte order"));
  in.expect(')', "closing the FAB byte order");
  in.expect(')', "closing the FAB real descriptor");
  std::vector<long long> little(bytes), big(bytes);
  for (int i = 0; i < bytes; ++i) {
    little[i] = bytes - i;
    big[i] = i + 1;
  }
  if (order != little && order != big)
    in.fail("the FAB byte order is neither little nor big endian");
  return {bytes, order == big};
}

double decode(const unsigned char* p, const RealFormat& format) {
  unsigned char bytes[8];
  std::memcpy(bytes, p, format.bytes);
  if (format.bigEndian != (std::endian::native == std::endian::big))
    std::reverse(bytes, bytes + format.bytes);
  if (format.bytes == 8) {
    double v;
    std::memcpy(&v, bytes, 8);
    return v;
  }
  float v;
  std::memcpy(&v, bytes, 4);
  return v;
}

// Reads one FAB's values, component-major over `stored` (the box grown by the ghost cells).
std::vector<double> readFab(const fs::path& file, long long offset, const Box& stored, int ncomp) {
  const std::string source = file.string();
  std::ifstream in(file, std::ios::binary | std::ios::ate);
  if (!in) throw InputError(source, "cannot open the FAB data file (Cell_D)");
  const long long fileSize = static_cast<long long>(in.tellg());
  if (offset >= fileSize)
    throw InputError(source, fmt::format("FAB offset {} is at or beyond the end of the {}-byte "
                                         "file",
                                         offset, fileSize));
  in.seekg(offset);
  std::string headerLine;
  std::getline(in, headerLine);
  const std::string where = fmt::format("{} (FAB at byte {})", source, offset);
  if (!in || headerLine.rfind("FAB ", 0) != 0)
    throw InputError(where, "the FAB header line does not start with 'FAB '");
  Cursor header(headerLine.substr(4), where, offset + 4);
  const RealFormat format = readRealFormat(header);
  const Box box = readBox(header, "the FAB box");
  const long long comps = header.integer("(the FAB component count)");
  if (!header.atEnd()) header.fail("unexpected text after the FAB component count");
  if (!(box == stored))
    throw InputError(
        where, fmt::format("the FAB box ({},{},{})-({},{},{}) differs from the "
                           "Cell_H box ({},{},{})-({},{},{})",
                           box.lo.x, box.lo.y, box.lo.z, box.hi.x, box.hi.y, box.hi.z, stored.lo.x,
                           stored.lo.y, stored.lo.z, stored.hi.x, stored.hi.y, stored.hi.z));
  if (comps != ncomp)
    throw InputError(where,
                     fmt::format("the FAB holds {} components, the plotfile {}", comps, ncomp));
  const long long dataStart = offset + static_cast<long long>(headerLine.size()) + 1;
  const long long dataBytes = box.count() * ncomp * format.bytes;
  if (dataStart + dataBytes > fileSize)
    throw InputError(where, fmt::format("truncated: the FAB needs {} data bytes from byte {} "
                                        "(up to byte {}), but the file has {} bytes",
                                        dataBytes, dataStart, dataStart + dataBytes, fileSize));
  std::vector<unsigned char> raw(static_cast<std::size_t>(dataBytes));
  if (!in.read(reinterpret_cast<char*>(raw.data()), dataBytes))
    throw InputError(where, "cannot read the FAB data");
  std::vector<double> values(static_cast<std::size_t>(box.count() * ncomp));
  for (std::size_t i = 0; i < values.size(); ++i)
    values[i] = decode(&raw[i * format.bytes], format);
  return values;
}

Box coarsen(const Box& box, int ratio) {
  auto down = [ratio](int v) { return v >= 0 ? v / ratio : -((-v + ratio - 1) / ratio); };
  return {glm::ivec3(down(box.lo.x), down(box.lo.y), down(box.lo.z)),
          glm::ivec3(down(box.hi.x), down(box.hi.y), down(box.hi.z))};
}

fs::path plotfileHeader(const fs::path& directory) {
  const fs::path headerPath = directory / "Header";
  if (!fs::is_regular_file(headerPath))
    throw InputError(directory.string(), "not an AMReX plotfile: no 'Header' file");
  return headerPath;
}

}  // namespace

bricks::AmrField readAmrexPlotfile(const fs::path& directory) {
  const fs::path headerPath = plotfileHeader(directory);
  const PlotHeader h = parseHeader(headerPath);
  const int levels = h.finestLevel + 1;
  const int ncomp = static_cast<int>(h.names.size());

  // widths[L] = finest cells per level-L cell.
  std::vector<int> widths(levels, 1);
  for (int l = h.finestLevel - 1; l >= 0; --l) {
    const long long width = static_cast<long long>(widths[l + 1]) * h.ratios[l];
    if (width > (1LL << bricks::kMaxLevel))
      throw InputError(headerPath.string(), "the refinement ratios exceed 2^20 in total");
    widths[l] = static_cast<int>(width);
  }
  const Box& finestDomain = h.domains[h.finestLevel];
  const glm::dvec3 spacing = (h.probHi - h.probLo) / glm::dvec3(finestDomain.size());
  for (int axis = 0; axis < 3; ++axis)
    if (std::abs(h.dx[h.finestLevel][axis] - spacing[axis]) > 1e-6 * spacing[axis])
      throw InputError(headerPath.string(),
                       fmt::format("finest dx {} differs from (prob_hi - prob_lo) / cells = {}",
                                   h.dx[h.finestLevel][axis], spacing[axis]));
  const bricks::WorldTransform transform{h.probLo, spacing};

  std::vector<LevelLayout> layouts;
  for (int l = 0; l < levels; ++l) {
    const fs::path cellH = directory / (h.levelPaths[l] + "_H");
    if (!fs::is_regular_file(cellH))
      throw InputError(cellH.string(), fmt::format("missing level-{} header", l));
    layouts.push_back(parseCellHeader(cellH, ncomp, h.gridCounts[l]));
  }

  std::vector<glm::ivec3> lowers;
  std::vector<std::uint8_t> ourLevels;
  std::vector<bricks::Channel> channels;
  for (const std::string& name : h.names) channels.push_back({name, {}});
  for (int l = 0; l < levels; ++l) {
    const fs::path levelDir = (directory / h.levelPaths[l]).parent_path();
    const int ourLevel = std::countr_zero(static_cast<unsigned>(widths[l]));
    std::vector<Box> covering;  // the finer level's boxes, coarsened to this level
    if (l < h.finestLevel) {
      const int ratio = h.ratios[l];
      for (const FabEntry& fine : layouts[l + 1].fabs) {
        if (glm::any(glm::notEqual(fine.box.lo % ratio, glm::ivec3(0))) ||
            glm::any(glm::notEqual((fine.box.hi + 1) % ratio, glm::ivec3(0))))
          throw InputError((directory / (h.levelPaths[l + 1] + "_H")).string(),
                           fmt::format("box ({},{},{})-({},{},{}) does not cover whole level-{} "
                                       "cells (ratio {})",
                                       fine.box.lo.x, fine.box.lo.y, fine.box.lo.z, fine.box.hi.x,
                                       fine.box.hi.y, fine.box.hi.z, l, ratio));
        covering.push_back(coarsen(fine.box, ratio));
      }
    }
    for (const FabEntry& fab : layouts[l].fabs) {
      const fs::path file = levelDir / fab.file;
      if (!fs::is_regular_file(file))
        throw InputError(file.string(),
                         fmt::format("missing FAB data file named in {}_H", h.levelPaths[l]));
      const Box stored{fab.box.lo - layouts[l].nghost, fab.box.hi + layouts[l].nghost};
      const std::vector<double> values = readFab(file, fab.offset, stored, ncomp);
      const glm::ivec3 size = fab.box.size();
      std::vector<bool> covered(static_cast<std::size_t>(fab.box.count()), false);
      for (const Box& cover : covering) {
        const glm::ivec3 lo = glm::max(cover.lo, fab.box.lo), hi = glm::min(cover.hi, fab.box.hi);
        for (int k = lo.z; k <= hi.z; ++k)
          for (int j = lo.y; j <= hi.y; ++j)
            for (int i = lo.x; i <= hi.x; ++i) {
              const glm::ivec3 local = glm::ivec3(i, j, k) - fab.box.lo;
              covered[(static_cast<std::size_t>(local.z) * size.y + local.y) * size.x + local.x] =
                  true;
            }
      }
      const glm::ivec3 storedSize = stored.size();
      const std::size_t points = static_cast<std::size_t>(stored.count());
      std::size_t index = 0;
      for (int k = 0; k < size.z; ++k)
        for (int j = 0; j < size.y; ++j)
          for (int i = 0; i < size.x; ++i, ++index) {
            if (covered[index]) continue;
            const glm::ivec3 cell = fab.box.lo + glm::ivec3(i, j, k);
            lowers.push_back(cell * widths[l] - finestDomain.lo);
            ourLevels.push_back(static_cast<std::uint8_t>(ourLevel));
            const glm::ivec3 s = glm::ivec3(i, j, k) + layouts[l].nghost;
            const std::size_t point =
                (static_cast<std::size_t>(s.z) * storedSize.y + s.y) * storedSize.x + s.x;
            for (int c = 0; c < ncomp; ++c)
              channels[c].values.push_back(static_cast<float>(values[c * points + point]));
          }
    }
  }
  bricks::AmrField field(std::move(lowers), std::move(ourLevels), std::move(channels), transform,
                         directory.string());
  std::vector<int> internalLevels;
  for (int width : widths) internalLevels.push_back(std::countr_zero(static_cast<unsigned>(width)));
  field.setInfo(readAmrexInfo(directory, h.time, internalLevels));
  return field;
}

double amrexPlotfileTime(const fs::path& directory) {
  return parseHeader(plotfileHeader(directory)).time;
}

}  // namespace amrstream::formats
