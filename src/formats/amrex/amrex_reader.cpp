#include "formats/amrex/amrex_reader.hpp"

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <exception>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "amrstream/error.hpp"
#include "formats/amrex/amrex_fab.hpp"
#include "formats/amrex/amrex_info.hpp"
#include "formats/amrex/amrex_text.hpp"
#include "formats/cell_checks.hpp"
#include "formats/cell_sink.hpp"
#include "formats/input_bytes.hpp"
#include "formats/text_numbers.hpp"
#include "util/input_file.hpp"

namespace amrstream::formats {
namespace {

namespace fs = std::filesystem;

using amrex::Box;
using amrex::boxText;
using amrex::Cursor;
using amrex::readBox;

// Ghost cells stored around each box; plotfiles store none.
constexpr int kMaxGhostCells = 1024;

struct PlotHeader {
  int axes = 3;  // 2 for a 2D plotfile, whose boxes are one cell thick in z at every level
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
  Cursor in(readWholeFile(path, "the plotfile Header"), path.string());
  PlotHeader h;
  const std::string version = in.line("the version line");
  if (version.rfind("HyperCLaw", 0) != 0)
    in.fail(fmt::format("version '{}' is not a HyperCLaw plotfile", excerpt(version)));
  const int ncomp = in.smallInt("the number of variables", 1, 100000);
  for (int c = 0; c < ncomp; ++c) h.names.push_back(in.line("a variable name"));
  h.axes = in.smallInt("the dimension", 1, 3);
  if (h.axes == 1) in.fail("the plotfile is 1D; amrstream reads 2D and 3D plotfiles");
  h.time = in.real("(the time)");
  h.finestLevel = in.smallInt("finest_level", 0, bricks::kMaxLevel);
  const int levels = h.finestLevel + 1;
  for (int axis = 0; axis < h.axes; ++axis) h.probLo[axis] = in.real("in prob_lo");
  for (int axis = 0; axis < h.axes; ++axis) h.probHi[axis] = in.real("in prob_hi");
  for (int axis = 0; axis < h.axes; ++axis)
    if (!(h.probHi[axis] > h.probLo[axis])) in.fail("prob_hi is not above prob_lo");
  for (int l = 0; l < h.finestLevel; ++l) {
    const int ratio = in.smallInt("a refinement ratio", 1, 1 << 20);
    if (!std::has_single_bit(static_cast<unsigned>(ratio)))
      in.fail(fmt::format("refinement ratio {} is not a power of two", ratio));
    h.ratios.push_back(ratio);
  }
  for (int l = 0; l < levels; ++l) h.domains.push_back(readBox(in, "a level domain box", h.axes));
  for (int l = 0; l < levels; ++l) in.integer("(a level step)");
  for (int l = 0; l < levels; ++l) {
    glm::dvec3 dx(0.0);
    for (int axis = 0; axis < h.axes; ++axis) dx[axis] = in.real("in a level's dx");
    h.dx.push_back(dx);
  }
  if (in.smallInt("coord_sys", 0, 2) != 0) in.fail("only Cartesian plotfiles (coord_sys 0)");
  in.integer("(bwidth)");
  for (int l = 0; l < levels; ++l) {
    if (in.integer("(the level number)") != l) in.fail(fmt::format("expected level {}", l));
    h.gridCounts.push_back(in.smallInt("a level's grid count", 1, 1 << 30));
    in.real("(the level time)");
    in.integer("(the level step)");
    for (long long g = 0; g < h.gridCounts.back() * static_cast<long long>(h.axes); ++g) {
      in.real("(a grid's lower extent)");
      in.real("(a grid's upper extent)");
    }
    const std::string levelPath = in.word("the level's path (Level_N/Cell)");
    const fs::path relative(levelPath);
    if (relative.is_absolute() || std::ranges::find(relative, "..") != relative.end())
      in.fail(fmt::format("level path '{}' leads outside the plotfile", excerpt(levelPath)));
    h.levelPaths.push_back(levelPath);
  }
  // Each level's domain is the coarser one refined by their ratio, and the finest spans fewer than
  // 2^kMaxExtentBits cells per axis: the boxes inside them then fit the cells' arithmetic.
  for (int l = 0; l < levels; ++l) {
    const glm::i64vec3 size = h.domains[l].size();
    for (int a = 0; a < 3; ++a)
      if (size[a] >= (std::int64_t{1} << bricks::kMaxExtentBits))
        throw InputError(path.string(),
                         fmt::format("the level-{} domain {} spans {} cells along axis {}; at "
                                     "most {} are supported",
                                     l, boxText(h.domains[l]), size[a], "xyz"[a],
                                     (std::int64_t{1} << bricks::kMaxExtentBits) - 1));
    if (l == 0) continue;
    const std::int64_t ratio = h.ratios[l - 1];
    glm::i64vec3 lo = glm::i64vec3(h.domains[l - 1].lo) * ratio;
    glm::i64vec3 hi =
        (glm::i64vec3(h.domains[l - 1].hi) + std::int64_t{1}) * ratio - std::int64_t{1};
    if (h.axes == 2) lo.z = hi.z = 0;
    if (lo != glm::i64vec3(h.domains[l].lo) || hi != glm::i64vec3(h.domains[l].hi))
      throw InputError(
          path.string(),
          fmt::format("the level-{} domain {} is not the level-{} domain {} refined "
                      "by {}",
                      l, boxText(h.domains[l]), l - 1, boxText(h.domains[l - 1]), ratio));
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

LevelLayout parseCellHeader(const fs::path& path, int ncomp, int gridCount, const Box& domain,
                            int level, int axes) {
  Cursor in(readWholeFile(path, "the level header (Cell_H)"), path.string());
  in.integer("(the version)");
  in.integer("(how)");
  const long long fileComps = in.integer("(ncomp)");
  if (fileComps != ncomp)
    in.fail(
        fmt::format("{} components, but the plotfile Header names {} variables", fileComps, ncomp));
  LevelLayout layout;
  layout.nghost = in.smallInt("nghost", 0, kMaxGhostCells);
  in.expect('(', "opening the BoxArray");
  const long long boxes = in.integer("(the box count)");
  if (boxes != gridCount)
    in.fail(fmt::format("{} boxes, but the plotfile Header lists {} grids", boxes, gridCount));
  in.integer("(the BoxArray tag)");
  // Entries are added as they are read: the declared count allocates nothing.
  for (long long b = 0; b < boxes; ++b) {
    const Box box = readBox(in, "a BoxArray box", axes);
    if (!domain.contains(box))
      in.fail(fmt::format("box {} {} lies outside the level-{} domain {}", b, boxText(box), level,
                          boxText(domain)));
    layout.fabs.push_back({box, {}, 0});
  }
  in.expect(')', "closing the BoxArray");
  if (in.integer("(the FAB count)") != boxes) in.fail("the FAB count differs from the box count");
  for (FabEntry& fab : layout.fabs) {
    if (in.word("'FabOnDisk:'") != "FabOnDisk:") in.fail("expected 'FabOnDisk: FILE OFFSET'");
    fab.file = in.word("a Cell_D file name");
    if (fab.file.find('/') != std::string::npos || fab.file == "..")
      in.fail(fmt::format("FAB file name '{}' is not a plain file name", excerpt(fab.file)));
    fab.offset = in.integer("(a FAB byte offset)");
    if (fab.offset < 0) in.fail("negative FAB byte offset");
  }
  return layout;
}

// Per Cell_D file, the offsets of its FABs in increasing order: a FAB's data ends where the next
// begins.
std::map<std::string, std::vector<long long>> fabOffsets(const LevelLayout& layout) {
  std::map<std::string, std::vector<long long>> offsets;
  for (const FabEntry& fab : layout.fabs) offsets[fab.file].push_back(fab.offset);
  for (auto& [file, list] : offsets) {
    std::ranges::sort(list);
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  return offsets;
}

std::optional<std::uint64_t> nextFabOffset(const std::vector<long long>& sorted, long long offset) {
  const auto next = std::ranges::upper_bound(sorted, offset);
  if (next == sorted.end()) return std::nullopt;
  return static_cast<std::uint64_t>(*next);
}

Box coarsen(const Box& box, int ratio) {
  auto down = [ratio](int v) { return v >= 0 ? v / ratio : -((-v + ratio - 1) / ratio); };
  return {glm::ivec3(down(box.lo.x), down(box.lo.y), down(box.lo.z)),
          glm::ivec3(down(box.hi.x), down(box.hi.y), down(box.hi.z))};
}

// A FAB left unread (outside a window) must still hold its box's values, at 4 bytes or more
// each: the box's cells are laid out from the layout alone.
void requireFabBytes(const fs::path& file, const FabEntry& fab,
                     const std::vector<long long>& offsets, const Box& stored, int ncomp) {
  const std::uint64_t size = regularFileSize(file);  // refuses directories and FIFOs by name
  const std::uint64_t end =
      nextFabOffset(offsets, fab.offset).value_or(std::max(size, std::uint64_t(fab.offset)));
  const std::uint64_t held = std::min(end, size) - std::min(std::uint64_t(fab.offset), size);
  const double needed = double(amrex::cellCount(stored, file.string())) * ncomp * 4.0;
  if (double(held) < needed)
    throw InputError(file.string(),
                     fmt::format("FAB at byte {} holds {} bytes, fewer than the {:.0f} its box {} "
                                 "needs",
                                 fab.offset, held, needed, boxText(fab.box)));
}

fs::path plotfileHeader(const fs::path& directory) {
  const fs::path headerPath = directory / "Header";
  std::error_code ec;
  if (!fs::exists(headerPath, ec))
    throw InputError(directory.string(), "not an AMReX plotfile: no 'Header' file");
  return headerPath;
}

void requireFile(const fs::path& path, const std::string& problem) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError(path.string(), problem);
}

// widths[L] = finest cells per level-L cell.
std::vector<int> levelWidths(const PlotHeader& h, const fs::path& headerPath) {
  std::vector<int> widths(std::size_t(h.finestLevel + 1), 1);
  for (int l = h.finestLevel - 1; l >= 0; --l) {
    const long long width = static_cast<long long>(widths[l + 1]) * h.ratios[l];
    if (width > (1LL << bricks::kMaxLevel))
      throw InputError(headerPath.string(), "the refinement ratios exceed 2^20 in total");
    widths[l] = static_cast<int>(width);
  }
  return widths;
}

// World positions of the finest cells, checked against the finest level's dx. A 2D plotfile's
// slab, `slabCells` finest cells thick, has cubic cells and its middle at z = 0.
WorldTransform finestTransform(const PlotHeader& h, const fs::path& headerPath, int slabCells) {
  const Box& finestDomain = h.domains[h.finestLevel];
  glm::dvec3 spacing = (h.probHi - h.probLo) / glm::dvec3(finestDomain.size());
  for (int axis = 0; axis < h.axes; ++axis) {
    if (!std::isnormal(spacing[axis]))
      throw InputError(headerPath.string(),
                       fmt::format("prob_lo {} to prob_hi {} over {} cells along axis {} gives "
                                   "cells {} wide",
                                   h.probLo[axis], h.probHi[axis], finestDomain.size()[axis],
                                   "xyz"[axis], spacing[axis]));
    if (!(std::abs(h.dx[h.finestLevel][axis] - spacing[axis]) <= 1e-6 * spacing[axis]))
      throw InputError(headerPath.string(),
                       fmt::format("finest dx {} differs from (prob_hi - prob_lo) / cells = {}",
                                   h.dx[h.finestLevel][axis], spacing[axis]));
  }
  glm::dvec3 origin = h.probLo;
  glm::ivec3 cells(finestDomain.size());
  if (h.axes == 2) {
    spacing.z = spacing.x;
    origin.z = -0.5 * slabCells * spacing.z;
    cells.z = slabCells;
  }
  const WorldTransform transform{origin, spacing};
  const glm::ivec3 domainCorners[] = {glm::ivec3(0), cells - 1};
  const std::uint8_t finestLevels[] = {0, 0};
  if (const auto problem = unrepresentablePositions(transform, domainCorners, finestLevels))
    throw InputError(headerPath.string(),
                     "prob_lo and prob_hi cannot place the cells: " + *problem);
  return transform;
}

// The plotfile's levels as the boxes' cells need them.
struct Plotfile {
  fs::path directory;
  PlotHeader header;
  std::vector<int> widths = {};
  // A 2D plotfile becomes a slab this many finest cells thick (the coarsest leaf's width): each
  // cell repeated along z as often as it fits.
  int slabCells = 1;
  std::vector<LevelLayout> layouts = {};
  std::vector<std::map<std::string, std::vector<long long>>> offsets = {};  // per level and file
  std::vector<std::vector<Box>> coverings = {};  // per level: the finer level's boxes, coarsened

  int components() const { return static_cast<int>(header.names.size()); }
  const Box& finestDomain() const { return header.domains[header.finestLevel]; }
  fs::path fabFile(int l, const FabEntry& fab) const {
    return (directory / header.levelPaths[l]).parent_path() / fab.file;
  }
  Box stored(int l, const FabEntry& fab) const {
    glm::ivec3 ghost(layouts[l].nghost);
    if (planar()) ghost.z = 0;
    return {fab.box.lo - ghost, fab.box.hi + ghost};
  }
  bool planar() const { return header.axes == 2; }
  int copies(int l) const { return planar() ? slabCells / widths[l] : 1; }
};

// The finer level's boxes coarsened to level l; each must cover whole level-l cells.
std::vector<Box> coveringBoxes(const Plotfile& plot, int l) {
  std::vector<Box> covering;
  if (l == plot.header.finestLevel) return covering;
  const int ratio = plot.header.ratios[l];
  const glm::ivec3 axes(1, 1, plot.planar() ? 0 : 1);
  for (const FabEntry& fine : plot.layouts[l + 1].fabs) {
    if (glm::any(glm::notEqual(fine.box.lo % ratio * axes, glm::ivec3(0))) ||
        glm::any(glm::notEqual((fine.box.hi + 1) % ratio * axes, glm::ivec3(0))))
      throw InputError((plot.directory / (plot.header.levelPaths[l + 1] + "_H")).string(),
                       fmt::format("box {} does not cover whole level-{} cells (ratio {})",
                                   boxText(fine.box), l, ratio));
    covering.push_back(coarsen(fine.box, ratio));
  }
  return covering;
}

// The level headers (each level's boxes and their FABs).
void readLevelHeaders(Plotfile& plot) {
  const PlotHeader& h = plot.header;
  for (int l = 0; l <= h.finestLevel; ++l) {
    const fs::path cellH = plot.directory / (h.levelPaths[l] + "_H");
    requireFile(cellH, fmt::format("missing level-{} header", l));
    plot.layouts.push_back(
        parseCellHeader(cellH, plot.components(), h.gridCounts[l], h.domains[l], l, h.axes));
  }
}

// A box with leaves, where its cells go (box after box: the cells' order) and whether its data
// is read.
struct FabPlan {
  int level = 0;
  const FabEntry* fab = nullptr;
  std::size_t at = 0;  // its first cell
  bool wanted = false;
};

std::uint64_t coveredCells(const std::vector<Box>& covering, const Box& box) {
  std::uint64_t covered = 0;
  for (const Box& cover : covering) {
    const glm::i64vec3 lo = glm::max(cover.lo, box.lo), hi = glm::min(cover.hi, box.hi);
    if (glm::all(glm::lessThanEqual(lo, hi))) {
      const glm::i64vec3 n = hi - lo + std::int64_t(1);
      covered += std::uint64_t(n.x * n.y * n.z);
    }
  }
  return covered;
}

// Per level and box, how many of its cells are leaves (not covered by the finer level). Fills
// the plotfile's coverings and FAB offsets, and the slab's thickness of a 2D plotfile.
std::vector<std::vector<std::uint64_t>> countLeaves(Plotfile& plot) {
  const PlotHeader& h = plot.header;
  std::vector<std::vector<std::uint64_t>> leaves;
  int coarsestWithLeaves = -1;
  for (int l = 0; l <= h.finestLevel; ++l) {
    plot.coverings.push_back(coveringBoxes(plot, l));
    plot.offsets.push_back(fabOffsets(plot.layouts[l]));
    leaves.emplace_back();
    for (const FabEntry& fab : plot.layouts[l].fabs) {
      requireFile(plot.fabFile(l, fab),
                  fmt::format("missing FAB data file named in {}_H", h.levelPaths[l]));
      const glm::i64vec3 boxCells = fab.box.size();
      const std::uint64_t cells = std::uint64_t(boxCells.x * boxCells.y * boxCells.z);
      leaves.back().push_back(cells - coveredCells(plot.coverings[std::size_t(l)], fab.box));
      if (leaves.back().back() > 0 && coarsestWithLeaves < 0) coarsestWithLeaves = l;
    }
  }
  if (plot.planar()) plot.slabCells = plot.widths[std::size_t(std::max(coarsestWithLeaves, 0))];
  return leaves;
}

// The boxes that have leaves (a box that finer boxes cover, as they are disjoint, has none: its
// data is not read), in the cells' order; `total` is their cell count, a 2D plotfile's cells
// repeated through the slab.
std::vector<FabPlan> planFabs(Plotfile& plot, const ValueWindow* window, WindowedRead* read,
                              bool skipsPieces, std::size_t& total) {
  const std::vector<std::vector<std::uint64_t>> leaves = countLeaves(plot);
  std::vector<FabPlan> plans;
  total = 0;
  std::uint64_t leafCells = 0;
  for (int l = 0; l <= plot.header.finestLevel; ++l) {
    const int width = plot.widths[l];
    for (std::size_t f = 0; f < plot.layouts[l].fabs.size(); ++f) {
      const FabEntry& fab = plot.layouts[l].fabs[f];
      const std::uint64_t cells = leaves[std::size_t(l)][f];
      glm::ivec3 lower = fab.box.lo * width - plot.finestDomain().lo;
      glm::ivec3 upper = (fab.box.hi + 1) * width - plot.finestDomain().lo;
      if (plot.planar()) lower.z = 0, upper.z = plot.slabCells;
      const bool wanted = cells > 0 && (!window || window->meets(lower, upper, width));
      if (read) {
        ++read->pieces;
        read->piecesRead += wanted;
      }
      if (cells == 0) continue;
      // The box's cells are laid out before any FAB is read: its FAB must hold them.
      requireFabBytes(plot.fabFile(l, fab), fab, plot.offsets[std::size_t(l)].at(fab.file),
                      plot.stored(l, fab), plot.components());
      if (wanted || !skipsPieces) plans.push_back({l, &fab, total, wanted});
      total += cells * std::uint64_t(plot.copies(l));
      leafCells += cells;
      if (total > kMaxSlabGrowth * leafCells)
        throw InputError(plot.directory.string(),
                         fmt::format("the 2D plotfile's cells become more than {} times as many "
                                     "when stacked into a slab of uniform thickness: its finest "
                                     "level is too many levels below the coarsest leaves",
                                     kMaxSlabGrowth));
    }
  }
  return plans;
}

// Which of the box's cells (x fastest) the finer level covers.
std::vector<bool> coveredMask(const Plotfile& plot, int l, const Box& box,
                              const std::string& file) {
  const glm::ivec3 size(box.size());
  std::vector<bool> covered(amrex::cellCount(box, file), false);
  for (const Box& cover : plot.coverings[std::size_t(l)]) {
    const glm::ivec3 lo = glm::max(cover.lo, box.lo), hi = glm::min(cover.hi, box.hi);
    for (int k = lo.z; k <= hi.z; ++k)
      for (int j = lo.y; j <= hi.y; ++j)
        for (int i = lo.x; i <= hi.x; ++i) {
          const glm::ivec3 local = glm::ivec3(i, j, k) - box.lo;
          covered[(static_cast<std::size_t>(local.z) * size.y + local.y) * size.x + local.x] = true;
        }
  }
  return covered;
}

// Places the box's leaf cells and, when it is wanted, sets their values from its FAB.
void readFabCells(const Plotfile& plot, const FabPlan& plan, CellSink& sink) {
  const int l = plan.level;
  const FabEntry& fab = *plan.fab;
  const fs::path file = plot.fabFile(l, fab);
  const Box stored = plot.stored(l, fab);
  const int ncomp = plot.components();
  const std::unique_ptr<double[]> values =
      plan.wanted
          ? amrex::readFab(file, static_cast<std::uint64_t>(fab.offset),
                           nextFabOffset(plot.offsets[std::size_t(l)].at(fab.file), fab.offset),
                           stored, ncomp, plot.header.axes)
          : nullptr;
  std::vector<float*> into(std::size_t(plan.wanted ? ncomp : 0), nullptr);
  for (std::size_t c = 0; c < into.size(); ++c) into[c] = sink.values(c).data();
  const std::vector<bool> covered = coveredMask(plot, l, fab.box, file.string());
  const int width = plot.widths[l];
  const auto ourLevel = static_cast<std::uint8_t>(std::countr_zero(unsigned(width)));
  const glm::ivec3 size(fab.box.size()), storedSize(stored.size());
  const glm::ivec3 ghost = fab.box.lo - stored.lo;
  const std::size_t points = amrex::cellCount(stored, file.string());
  const int copies = plot.copies(l);
  std::size_t index = 0, at = plan.at;
  for (int k = 0; k < size.z; ++k)
    for (int j = 0; j < size.y; ++j)
      for (int i = 0; i < size.x; ++i, ++index) {
        if (covered[index]) continue;
        const glm::ivec3 cell = fab.box.lo + glm::ivec3(i, j, k);
        const glm::ivec3 s = glm::ivec3(i, j, k) + ghost;
        const std::size_t point =
            (static_cast<std::size_t>(s.z) * storedSize.y + s.y) * storedSize.x + s.x;
        for (int copy = 0; copy < copies; ++copy, ++at) {
          glm::ivec3 lower = cell * width - plot.finestDomain().lo;
          if (plot.planar()) lower.z = copy * width;
          sink.place(at, lower, ourLevel);
          for (std::size_t c = 0; c < into.size(); ++c) {
            const double value = values[c * points + point];
            if (std::abs(value) <= kLargestFieldValue) {  // the usual case, NaN excluded
              if (into[c]) into[c][at] = static_cast<float>(value);
              continue;
            }
            if (const auto problem = unusableFieldValue(value))
              throw InputError(
                  file.string(),
                  fmt::format("FAB at byte {}: variable '{}' at level-{} cell "
                              "{} is {} ({})",
                              fab.offset, plot.header.names[c], l,
                              plot.planar() ? fmt::format("({}, {})", cell.x, cell.y)
                                            : fmt::format("({}, {}, {})", cell.x, cell.y, cell.z),
                              *problem, value));
          }
        }
      }
}

}  // namespace

bricks::AmrField readAmrexPlotfile(const fs::path& directory, const ValueWindow* window,
                                   WindowedRead* read) {
  const fs::path headerPath = plotfileHeader(directory);
  Plotfile plot{directory, parseHeader(headerPath)};
  plot.widths = levelWidths(plot.header, headerPath);
  finestTransform(plot.header, headerPath, 1);  // the header's own numbers, before the boxes
  readLevelHeaders(plot);

  CellSink sink(window, directory.string(), read);
  for (const std::string& name : plot.header.names) sink.addChannel(name);
  std::size_t total = 0;
  const std::vector<FabPlan> plans = planFabs(plot, window, read, sink.skipsPieces(), total);
  const WorldTransform transform = finestTransform(plot.header, headerPath, plot.slabCells);
  sink.presize(total);
  std::vector<std::exception_ptr> failures(plans.size());
  tbb::parallel_for(std::size_t(0), plans.size(), [&](std::size_t p) {
    try {
      readFabCells(plot, plans[p], sink);
    } catch (...) {
      failures[p] = std::current_exception();
    }
  });
  // The first box's failure in the cells' order, as one box after another would meet it.
  for (const std::exception_ptr& failure : failures)
    if (failure) std::rethrow_exception(failure);

  bricks::AmrField field = sink.finish(transform);
  std::vector<int> internalLevels;
  for (int width : plot.widths)
    internalLevels.push_back(std::countr_zero(static_cast<unsigned>(width)));
  field.setInfo(readAmrexInfo(directory, plot.header.time, internalLevels, plot.header.axes));
  return field;
}

double amrexPlotfileTime(const fs::path& directory) {
  return parseHeader(plotfileHeader(directory)).time;
}

}  // namespace amrstream::formats
