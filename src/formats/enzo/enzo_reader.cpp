#include "formats/enzo/enzo_reader.hpp"

#include <fmt/format.h>
#include <hdf5.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <exception>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "amrstream/error.hpp"
#include "formats/cell_checks.hpp"
#include "formats/cell_sink.hpp"
#include "formats/enzo/enzo_fields.hpp"
#include "formats/enzo/enzo_grid_headers.hpp"
#include "formats/enzo/enzo_info.hpp"
#include "formats/enzo/enzo_parameters.hpp"
#include "formats/hdf5_checks.hpp"
#include "formats/hdf5_handle.hpp"
#include "formats/input_bytes.hpp"
#include "formats/text_numbers.hpp"
#include "util/input_file.hpp"

namespace amrstream::formats {
namespace {

namespace fs = std::filesystem;

using Handle = Hdf5Handle;

Handle checked(hid_t id, herr_t (*close)(hid_t), const fs::path& file, const std::string& what) {
  if (id < 0) throw InputError(file.string(), fmt::format("HDF5 could not {}", what));
  return Handle(id, close);
}

struct Grid {
  int id = 0;  // 1-based, as in the files
  glm::dvec3 left{0.0}, right{0.0};
  glm::ivec3 dims{0};   // active zones, x y z
  int level = -1;       // Enzo level (0 = root), -1 until known
  std::string file;     // basename of the field file
  glm::ivec3 lower{0};  // in finest-cell units
  int width = 1;        // cell width in finest cells
};

struct Domain {
  glm::dvec3 left{0.0}, right{1.0};
  glm::ivec3 topDims{0};
  int axes = 3;  // 2: planar data, whose grids are one zone thick (z is then unused)
};

// Active zones per grid axis and per grid: beyond these no grid fits the cells' extent or this
// machine's memory.
constexpr std::int64_t kMaxZonesPerAxis = std::int64_t{1} << bricks::kMaxExtentBits;
constexpr std::int64_t kMaxZonesPerGrid = std::int64_t{1} << 31;
// Active zones in all grids, covered ones included: a hierarchy claiming more is not laid out.
constexpr std::uint64_t kMaxTotalZones = std::uint64_t{1} << 32;

glm::ivec3 toIvec3(const std::array<std::int64_t, 3>& v) {
  return glm::ivec3(static_cast<int>(v[0]), static_cast<int>(v[1]), static_cast<int>(v[2]));
}
glm::dvec3 toDvec3(const std::array<double, 3>& v) { return glm::dvec3(v[0], v[1], v[2]); }

// The grid's active zones, or an InputError unless they are 1 to kMaxZonesPerAxis per axis and at
// most kMaxZonesPerGrid in all, before anything is allocated for them.
glm::ivec3 requireGridSize(int id, const glm::i64vec3& dims, const std::string& table) {
  for (int a = 0; a < 3; ++a)
    if (dims[a] < 1 || dims[a] > kMaxZonesPerAxis)
      throw InputError(table, fmt::format("grid {} has {} active zones along axis {} (expected 1 "
                                          "to {})",
                                          id, dims[a], "xyz"[a], kMaxZonesPerAxis));
  const glm::u64vec3 size(dims);  // up to 2^21 each: the product fits in 64 bits unsigned
  const std::uint64_t zones = size.x * size.y * size.z;
  if (zones > std::uint64_t(kMaxZonesPerGrid))
    throw InputError(table, fmt::format("grid {} has {} x {} x {} = {} active zones, more than "
                                        "the {} accepted",
                                        id, dims.x, dims.y, dims.z, zones, kMaxZonesPerGrid));
  return glm::ivec3(dims);
}

Domain readParameters(const EnzoParameters& parameters) {
  const auto& kv = parameters.values();
  const std::string file = parameters.file().string();
  auto need = [&](const char* key) -> const std::string& {
    const auto it = kv.find(key);
    if (it == kv.end()) throw InputError(file, fmt::format("missing {}", key));
    return it->second;
  };
  Domain d;
  if (kv.contains("TopGridRank"))
    d.axes = static_cast<int>(parseInteger(need("TopGridRank"), file, "TopGridRank", 1, 3));
  if (d.axes == 1) throw InputError(file, "TopGridRank is 1: 1D data is not read (2D and 3D are)");
  d.topDims = toIvec3(parseAxisIntegers(need("TopGridDimensions"), file, "TopGridDimensions", 1,
                                        kMaxZonesPerAxis, d.axes, 1));
  d.left = toDvec3(parseAxisFinite(need("DomainLeftEdge"), file, "DomainLeftEdge", d.axes, 0.0));
  d.right = toDvec3(parseAxisFinite(need("DomainRightEdge"), file, "DomainRightEdge", d.axes, 1.0));
  if (const auto it = kv.find("RefineBy"); it != kv.end()) {
    const std::int64_t refineBy = parseInteger(it->second, file, "RefineBy", 1, 1 << 30);
    if (refineBy != 2)
      throw InputError(file, fmt::format("RefineBy {} is not supported (only 2)", refineBy));
  }
  return d;
}

// "Pointer: Grid[A]->NextGridWHICH" = TARGET (blanks after the colon optional); false when the
// key is not of that form.
bool parsePointer(std::string_view key, std::string_view value, const std::string& where,
                  std::int64_t& grid, std::string& which, std::int64_t& target) {
  constexpr std::string_view kPointer = "Pointer:", kGrid = "Grid[", kArrow = "]->NextGrid";
  if (!key.starts_with(kPointer)) return false;
  key.remove_prefix(kPointer.size());
  while (!key.empty() && (key.front() == ' ' || key.front() == '\t')) key.remove_prefix(1);
  if (!key.starts_with(kGrid)) return false;
  const std::size_t close = key.find(kArrow);
  if (close == std::string_view::npos) return false;
  grid = parseInteger(key.substr(kGrid.size(), close - kGrid.size()), where, "a pointer's grid", 1,
                      std::numeric_limits<std::int32_t>::max());
  which = std::string(key.substr(close + kArrow.size()));
  const auto words = splitWords(value);
  if (words.empty()) return false;
  target = parseInteger(words.front(), where, "a pointer's target grid", 0,
                        std::numeric_limits<std::int32_t>::max());
  return true;
}

// The text hierarchy: blocks `Grid = N` of `Key = value` lines, then `Pointer:` lines. `axes`:
// the grids' rank (GridRank, 2 or 3, the same for all); a 2D grid is one zone thick.
std::vector<Grid> readHierarchy(const fs::path& file, int& axes) {
  const std::string source = file.string();
  const std::string text = readWholeFile(file, "the hierarchy file");
  std::vector<std::map<std::string, std::string>> blocks;
  std::set<std::pair<std::int64_t, std::string>> pointers;  // (grid, ThisLevel/NextLevel)
  std::int64_t maxTarget = 0;
  std::size_t lineStart = 0;
  for (int number = 1; lineStart < text.size(); ++number) {
    const std::size_t lineEnd = std::min(text.find('\n', lineStart), text.size());
    const std::string_view line = std::string_view(text).substr(lineStart, lineEnd - lineStart);
    lineStart = lineEnd + 1;
    const auto eq = line.find('=');
    if (eq == std::string_view::npos) continue;
    const std::string_view key = trimmed(line.substr(0, eq));
    const std::string_view value = trimmed(line.substr(eq + 1));
    if (key == "Grid") {
      if (value != std::to_string(blocks.size() + 1))
        throw InputError(
            fmt::format("{}:{}", source, number),
            fmt::format("expected Grid = {}, got Grid = {}", blocks.size() + 1, excerpt(value)));
      blocks.emplace_back();
    } else if (key.starts_with("Pointer:")) {
      const std::string where = fmt::format("{}:{}", source, number);
      std::int64_t grid = 0, target = 0;
      std::string which;
      if (!parsePointer(key, value, where, grid, which, target))
        throw InputError(where,
                         fmt::format("cannot parse '{}' (truncated?)", excerpt(trimmed(line))));
      pointers.emplace(grid, which);
      maxTarget = std::max(maxTarget, target);
    } else if (!blocks.empty()) {
      blocks.back()[std::string(key)] = std::string(value);
    }
  }
  const std::size_t n = blocks.size();
  if (n == 0) throw InputError(source, "no grids (no `Grid = 1` line)");
  if (maxTarget > static_cast<std::int64_t>(n))
    throw InputError(
        source, fmt::format("a pointer names grid {} but only {} grids are listed (truncated?)",
                            maxTarget, n));
  std::vector<Grid> grids;
  for (std::size_t i = 0; i < n; ++i) {
    const auto& b = blocks[i];
    const int id = static_cast<int>(i) + 1;
    auto need = [&](const char* key) -> const std::string& {
      const auto it = b.find(key);
      if (it == b.end())
        throw InputError(source, fmt::format("grid {} lacks {} (truncated?)", id, key));
      return it->second;
    };
    for (const char* which : {"ThisLevel", "NextLevel"})
      if (!pointers.contains({id, which}))
        throw InputError(
            source, fmt::format("grid {} lacks its NextGrid{} pointer (truncated?)", id, which));
    Grid g;
    g.id = id;
    const std::string what = fmt::format("grid {} ", id);
    const int rank =
        static_cast<int>(parseInteger(need("GridRank"), source, what + "GridRank", 2, 3));
    if (i > 0 && rank != axes)
      throw InputError(
          source, fmt::format("grid {}: GridRank {} differs from grid 1's {}", id, rank, axes));
    axes = rank;
    const std::int64_t kIntMax = std::numeric_limits<std::int32_t>::max();
    const auto start = parseAxisIntegers(need("GridStartIndex"), source, what + "GridStartIndex", 0,
                                         kIntMax, rank, 0);
    const auto end =
        parseAxisIntegers(need("GridEndIndex"), source, what + "GridEndIndex", 0, kIntMax, rank, 0);
    const auto total = parseAxisIntegers(need("GridDimension"), source, what + "GridDimension", 1,
                                         kIntMax, rank, 1);
    glm::i64vec3 dims;
    for (int a = 0; a < 3; ++a) {
      if (end[a] >= total[a] || end[a] < start[a])
        throw InputError(source, fmt::format("grid {}: start/end index {}..{} along axis {} is "
                                             "not inside GridDimension {}",
                                             id, start[a], end[a], "xyz"[a], total[a]));
      dims[a] = end[a] - start[a] + 1;
    }
    g.dims = requireGridSize(id, dims, source);
    g.left =
        toDvec3(parseAxisFinite(need("GridLeftEdge"), source, what + "GridLeftEdge", rank, 0.0));
    g.right =
        toDvec3(parseAxisFinite(need("GridRightEdge"), source, what + "GridRightEdge", rank, 1.0));
    if (const auto it = b.find("Level"); it != b.end())
      g.level = static_cast<int>(parseInteger(it->second, source, what + "Level", 0, kIntMax));
    // An absolute path from the machine that wrote it: only the basename is meaningful.
    g.file = fs::path(need("BaryonFileName")).filename().string();
    grids.push_back(g);
  }
  return grids;
}

std::vector<hsize_t> shapeOf(hid_t dataset, const fs::path& file, const std::string& name) {
  const auto space = checked(H5Dget_space(dataset), H5Sclose, file, "get the shape of " + name);
  const int rank = H5Sget_simple_extent_ndims(space.get());
  if (rank < 0 || rank > H5S_MAX_RANK)
    throw InputError(file.string(), fmt::format("HDF5 could not get the rank of {}", name));
  std::vector<hsize_t> dims(rank);
  if (rank > 0 && H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr) < 0)
    throw InputError(file.string(), fmt::format("HDF5 could not get the shape of {}", name));
  return dims;
}

template <typename T>
std::vector<T> readTable(hid_t h5file, const fs::path& file, const char* name, hid_t memType,
                         std::vector<hsize_t> expected) {
  const auto ds = checked(H5Dopen2(h5file, name, H5P_DEFAULT), H5Dclose, file,
                          fmt::format("open dataset {}", name));
  if (shapeOf(ds.get(), file, name) != expected)
    throw InputError(file.string(), fmt::format("dataset {} has an unexpected shape", name));
  std::vector<T> values(requireStoredValues(ds.get(), file.string(), name));
  if (H5Dread(ds.get(), memType, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0)
    throw InputError(file.string(), fmt::format("HDF5 could not read dataset {}", name));
  return values;
}

// Every grid's group and datasets are opened once: evicting an object's metadata from libhdf5's
// cache when it is closed keeps the cache small, and opening thousands of datasets a quarter
// faster (0.87 -> 0.63 s for 23,096 on one core). Only advice: without it the file opens as usual.
Handle openHdf5(const fs::path& file) {
  regularFileSize(file);  // refuses a directory or FIFO before HDF5 opens it
  const Handle access =
      checked(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, file, "make a file access property list");
  H5Pset_evict_on_close(access.get(), true);
  return checked(H5Fopen(file.c_str(), H5F_ACC_RDONLY, access.get()), H5Fclose, file,
                 "open the file (not HDF5, truncated or corrupt?)");
}

// The HDF5 grid table: LeftEdges, RightEdges, ActiveDimensions (n,3, x y z), Level (n).
std::vector<Grid> readHarrays(const fs::path& file) {
  const auto h5 = openHdf5(file);
  const auto ds =
      checked(H5Dopen2(h5.get(), "Level", H5P_DEFAULT), H5Dclose, file, "open dataset Level");
  const auto shape = shapeOf(ds.get(), file, "Level");
  if (shape.size() != 1 || shape[0] == 0)
    throw InputError(file.string(), "dataset Level must be a non-empty 1D array");
  const hsize_t n = shape[0];
  const auto levels = readTable<int>(h5.get(), file, "Level", H5T_NATIVE_INT, {n});
  const auto lefts = readTable<double>(h5.get(), file, "LeftEdges", H5T_NATIVE_DOUBLE, {n, 3});
  const auto rights = readTable<double>(h5.get(), file, "RightEdges", H5T_NATIVE_DOUBLE, {n, 3});
  const auto dims = readTable<int>(h5.get(), file, "ActiveDimensions", H5T_NATIVE_INT, {n, 3});
  std::vector<Grid> grids(n);
  for (hsize_t i = 0; i < n; ++i) {
    auto& g = grids[i];
    g.id = static_cast<int>(i) + 1;
    g.level = levels[i];
    g.left = {lefts[3 * i], lefts[3 * i + 1], lefts[3 * i + 2]};
    g.right = {rights[3 * i], rights[3 * i + 1], rights[3 * i + 2]};
    g.dims = requireGridSize(g.id, glm::i64vec3(dims[3 * i], dims[3 * i + 1], dims[3 * i + 2]),
                             file.string());
  }
  return grids;
}

// Sets level (checked against the cell size), lower and width of every grid; returns the finest
// dx. Every grid must lie inside the domain, which spans fewer than 2^kMaxExtentBits finest cells
// per axis, so the cells' integer arithmetic cannot overflow.
glm::dvec3 placeGrids(std::vector<Grid>& grids, const Domain& domain, const fs::path& table) {
  const auto src = table.string();
  const int axes = domain.axes;
  glm::dvec3 topDx = (domain.right - domain.left) / glm::dvec3(domain.topDims);
  if (axes == 2) topDx.z = topDx.x;  // the slab's cells are cubes
  for (int a = 0; a < axes; ++a)
    if (!std::isnormal(topDx[a]) || !(topDx[a] > 0))
      throw InputError(
          src, fmt::format("the domain [{}, {}] along axis {} over {} top-grid "
                           "cells gives cells {} wide",
                           domain.left[a], domain.right[a], "xyz"[a], domain.topDims[a], topDx[a]));
  int finest = 0;
  for (auto& g : grids) {
    if (axes == 2) g.dims.z = 1;  // z is unused: its edges and zones are not checked
    for (int a = 0; a < axes; ++a)
      if (!std::isfinite(g.left[a]) || !std::isfinite(g.right[a]) || !(g.right[a] > g.left[a]))
        throw InputError(src, fmt::format("grid {} spans [{}, {}] along axis {}", g.id, g.left[a],
                                          g.right[a], "xyz"[a]));
    const glm::dvec3 ratio = topDx * glm::dvec3(g.dims) / (g.right - g.left);
    const double log2Ratio = std::log2(ratio.x);
    if (!(log2Ratio > -0.5 && log2Ratio < bricks::kMaxLevel + 0.5))
      throw InputError(src, fmt::format("grid {}: its cells are 1/{} of a top-grid cell, not "
                                        "1/2^L for a level L in 0..{}",
                                        g.id, ratio.x, bricks::kMaxLevel));
    const int level = static_cast<int>(std::lround(log2Ratio));
    for (int a = 0; a < axes; ++a)
      if (!(std::abs(ratio[a] / std::ldexp(1.0, level) - 1.0) < 1e-6))
        throw InputError(src, fmt::format("grid {}: cell size is not the top-grid cell size / 2^L "
                                          "(edges and dimensions disagree)",
                                          g.id));
    if (g.level >= 0 && g.level != level)
      throw InputError(
          src, fmt::format("grid {}: Level {} but its cell size says {}", g.id, g.level, level));
    g.level = level;
    finest = std::max(finest, level);
  }
  const glm::dvec3 finestDx = topDx / std::ldexp(1.0, finest);
  const glm::i64vec3 domainCells = glm::i64vec3(domain.topDims) << std::int64_t(finest);
  for (int a = 0; a < axes; ++a)
    if (domainCells[a] >= kMaxZonesPerAxis)
      throw InputError(src, fmt::format("the domain spans {} finest cells along axis {} ({} "
                                        "top-grid cells refined {} times); at most {} are "
                                        "supported",
                                        domainCells[a], "xyz"[a], domain.topDims[a], finest,
                                        kMaxZonesPerAxis - 1));
  for (auto& g : grids) {
    g.width = 1 << (finest - g.level);
    const glm::dvec3 lo = (g.left - domain.left) / finestDx;
    const glm::dvec3 hi = (g.right - domain.left) / finestDx;
    g.lower.z = 0;
    for (int a = 0; a < axes; ++a) {
      const std::int64_t upper = std::int64_t{g.dims[a]} * g.width;
      if (!(lo[a] > -0.5 && lo[a] + upper < domainCells[a] + 0.5))
        throw InputError(src, fmt::format("grid {} spans [{}, {}] along axis {}, outside the "
                                          "domain [{}, {}]",
                                          g.id, g.left[a], g.right[a], "xyz"[a], domain.left[a],
                                          domain.right[a]));
      g.lower[a] = static_cast<int>(std::lround(lo[a]));
      const double up = static_cast<double>(g.lower[a]) + static_cast<double>(upper);
      if (std::abs(lo[a] - g.lower[a]) > 1e-3 || !(std::abs(hi[a] - up) <= 1e-3) ||
          g.lower[a] % g.width != 0)
        throw InputError(src, fmt::format("grid {} is not aligned to its level's cells", g.id));
    }
  }
  return finestDx;
}

// Marks the cells of `g` covered by grids one level finer. Those align with g's cells; deeper grids
// nest inside them (a violation shows up as an overlap in AmrField).
std::vector<bool> coveredCells(const Grid& g, const std::vector<Grid>& grids, const fs::path& table,
                               int axes) {
  const glm::ivec3 n = g.dims;
  std::vector<bool> covered(std::size_t(n.x) * n.y * n.z, false);
  const glm::ivec3 gUpper = g.lower + n * g.width;
  for (const auto& h : grids) {
    if (h.level != g.level + 1) continue;
    glm::ivec3 lo = glm::max(g.lower, h.lower) - g.lower;
    glm::ivec3 hi = glm::min(gUpper, h.lower + h.dims * h.width) - g.lower;
    if (axes == 2) lo.z = 0, hi.z = g.width;  // planar grids cover along x and y only
    if (glm::any(glm::lessThanEqual(hi, lo))) continue;
    for (int a = 0; a < 3; ++a)
      if (lo[a] % g.width != 0 || hi[a] % g.width != 0)
        throw InputError(table.string(),
                         fmt::format("grid {} covers only part of a cell of grid {}", h.id, g.id));
    const glm::ivec3 c0 = lo / g.width, c1 = hi / g.width;
    for (int k = c0.z; k < c1.z; ++k)
      for (int j = c0.y; j < c1.y; ++j)
        for (int i = c0.x; i < c1.x; ++i) covered[(std::size_t(k) * n.y + j) * n.x + i] = true;
  }
  return covered;
}

herr_t collectName(hid_t, const char* name, const H5L_info_t*, void* out) {
  static_cast<std::vector<std::string>*>(out)->emplace_back(name);
  return 0;
}

struct Siblings {
  fs::path dir, parameter, hierarchy, harrays;
};

// A path that is there, whatever it is: reading it then refuses a directory or FIFO by name.
bool present(const fs::path& path) {
  std::error_code ec;
  return fs::exists(path, ec);
}

Siblings findSiblings(const fs::path& file) {
  regularFileSize(file);
  fs::path base = file;
  const auto ext = file.extension().string();
  if (const auto companion = enzoCompanionOf(file)) {
    base = *companion;  // .boundary, .boundary.hdf, .procmap, ...
  } else if (ext == ".hierarchy" || ext == ".harrays" || ext.starts_with(".cpu")) {
    base.replace_extension();
  }
  Siblings s;
  s.dir = file.parent_path();
  s.parameter = base;
  s.hierarchy = base.string() + ".hierarchy";
  s.harrays = base.string() + ".harrays";
  return s;
}

// The grid table, from `.harrays` when present (with the field files the hierarchy names, if
// any), else from `.hierarchy`.
struct GridTable {
  std::vector<Grid> grids;
  fs::path table;
  int axes = 3;  // the hierarchy's GridRank; 3 without a hierarchy
};

GridTable readGridTable(const fs::path& file, const Siblings& sib) {
  const bool hasHierarchy = present(sib.hierarchy);
  const bool hasHarrays = present(sib.harrays);
  if (!hasHierarchy && !hasHarrays)
    throw InputError(file.string(),
                     fmt::format("neither {} nor {} exists", sib.hierarchy.filename().string(),
                                 sib.harrays.filename().string()));

  std::vector<Grid> grids;
  fs::path table;
  std::vector<Grid> text;
  int axes = 3;
  if (hasHierarchy) text = readHierarchy(sib.hierarchy, axes);
  if (hasHarrays) {
    table = sib.harrays;
    grids = readHarrays(sib.harrays);
    if (hasHierarchy && text.size() != grids.size())
      throw InputError(sib.hierarchy.string(),
                       fmt::format("lists {} grids but {} lists {}", text.size(),
                                   sib.harrays.filename().string(), grids.size()));
    for (std::size_t i = 0; i < grids.size(); ++i)
      grids[i].file = hasHierarchy ? text[i].file : sib.parameter.filename().string() + ".cpu0000";
  } else {
    table = sib.hierarchy;
    grids = std::move(text);
  }
  return {std::move(grids), std::move(table), axes};
}

// The domain from the parameter file, read into `parameters`, when there is one.
Domain readDomain(const Siblings& sib, const GridTable& table,
                  std::optional<EnzoParameters>& parameters) {
  Domain domain;
  std::error_code ec;
  if (present(sib.parameter) && !fs::is_directory(sib.parameter, ec)) {
    parameters.emplace(sib.parameter);
    domain = readParameters(*parameters);
    if (present(sib.hierarchy) && domain.axes != table.axes)
      throw InputError(sib.hierarchy.string(),
                       fmt::format("its grids have GridRank {}, but {} says TopGridRank {}",
                                   table.axes, sib.parameter.filename().string(), domain.axes));
  } else {
    // Without the parameter file, the first grid is the root grid spanning the domain.
    domain.left = table.grids[0].left;
    domain.right = table.grids[0].right;
    domain.topDims = table.grids[0].dims;
    domain.axes = table.axes;
  }
  return domain;
}

// The thickness, in finest cells, of the slab that holds 2D data: its coarsest leaf cell's
// width. Refused when repeating the finer cells through it multiplies them by more than
// kMaxSlabGrowth.
int slabThickness(const std::vector<Grid>& grids, const fs::path& table) {
  int thickest = 1;
  std::vector<std::size_t> leaves(grids.size());
  for (std::size_t n = 0; n < grids.size(); ++n) {
    const auto covered = coveredCells(grids[n], grids, table, 2);
    leaves[n] = std::size_t(std::count(covered.begin(), covered.end(), false));
    if (leaves[n] > 0) thickest = std::max(thickest, grids[n].width);
  }
  std::size_t leafCells = 0, cells = 0;
  for (std::size_t n = 0; n < grids.size(); ++n) {
    leafCells += leaves[n];
    cells += leaves[n] * std::size_t(thickest / grids[n].width);
  }
  if (cells > kMaxSlabGrowth * leafCells)
    throw InputError(table.string(),
                     fmt::format("the 2D data's {} leaf cells become {} when stacked into a slab "
                                 "of uniform thickness, more than {} times as many: its finest "
                                 "level is too many levels below the coarsest leaves",
                                 leafCells, cells, kMaxSlabGrowth));
  return thickest;
}

// Reading the grids' cells into a sink: the field files, each opened once, and the channels,
// named by the first grid read.
struct GridReading {
  const std::vector<Grid>& grids;
  const fs::path& table;
  const fs::path& dir;
  int finest;
  int axes;
  int slabCells;  // 2D data: each cell repeats along z up to this many finest cells
  CellSink& sink;
  std::vector<std::string> channels;
  std::map<std::string, Handle> files;
};

// The channels: every dataset of the first grid read but the particles' (particle_*).
void listChannels(GridReading& r, hid_t group, const fs::path& path, const std::string& groupName) {
  std::vector<std::string> names;
  if (H5Literate(group, H5_INDEX_NAME, H5_ITER_INC, nullptr, collectName, &names) < 0)
    throw InputError(path.string(), fmt::format("HDF5 could not list group {}", groupName));
  for (auto& name : names)
    if (!name.starts_with("particle_")) r.channels.push_back(name);
  if (r.channels.empty())
    throw InputError(path.string(), fmt::format("group {} has no field datasets", groupName));
  for (const std::string& name : r.channels) r.sink.addChannel(name);
}

// Per grid: its zones that finer grids cover, whether its values are read (it meets the window,
// if any) and where its cells begin; `total` cells in all.
struct GridCells {
  std::vector<std::vector<bool>> covered;
  std::vector<char> wanted;
  std::vector<std::size_t> first;
  std::size_t total = 0;
};

GridCells gridCells(const GridReading& r, const ValueWindow* window) {
  std::uint64_t zones = 0;
  for (const Grid& g : r.grids) zones += std::uint64_t(g.dims.x) * g.dims.y * g.dims.z;
  if (zones > kMaxTotalZones)
    throw InputError(r.table.string(), fmt::format("the grids hold {} active zones, more than "
                                                   "the {} accepted",
                                                   zones, kMaxTotalZones));
  const std::size_t n = r.grids.size();
  GridCells cells;
  cells.covered.resize(n);
  cells.wanted.resize(n);
  cells.first.resize(n);
  // Each grid's cells, on all cores; the first grid's error (in the table's order) is thrown.
  std::vector<std::size_t> counts(n);
  std::vector<std::exception_ptr> errors(n);
  tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) {
    const Grid& g = r.grids[i];
    glm::ivec3 upper = g.lower + g.dims * g.width;
    if (r.axes == 2) upper.z = r.slabCells;
    cells.wanted[i] = !window || window->meets(g.lower, upper, g.width);
    try {
      cells.covered[i] = coveredCells(g, r.grids, r.table, r.axes);
    } catch (...) {
      errors[i] = std::current_exception();
      return;
    }
    const int copies = r.axes == 2 ? r.slabCells / g.width : 1;
    const auto& covered = cells.covered[i];
    counts[i] = std::size_t(std::count(covered.begin(), covered.end(), false)) * copies;
  });
  for (std::size_t i = 0; i < n; ++i) {
    if (errors[i]) std::rethrow_exception(errors[i]);
    cells.first[i] = cells.total;
    cells.total += counts[i];
  }
  return cells;
}

// The grid's group in its field file, opened once.
Handle openGroup(GridReading& r, const Grid& g) {
  const fs::path path = r.dir / g.file;
  auto it = r.files.find(g.file);
  if (it == r.files.end()) {
    if (!present(path))
      throw InputError(path.string(), fmt::format("grid {}'s field file is missing", g.id));
    it = r.files.emplace(g.file, openHdf5(path)).first;
  }
  const auto groupName = fmt::format("/Grid{:08d}", g.id);
  return checked(H5Gopen2(it->second.get(), groupName.c_str(), H5P_DEFAULT), H5Gclose, path,
                 fmt::format("open group {}", groupName));
}

// The grids' groups and datasets from their object headers: the field files the grids name,
// those libhdf5 opens (a missing or unreadable one is reported by openGroup, in the grids' order).
std::vector<enzo::GridDatasets> findDatasets(GridReading& r, const GridCells& cells) {
  std::vector<enzo::FieldFile> files;
  std::vector<char> tried;  // per file: libhdf5 asked to open it
  std::map<std::string, std::size_t> fileIndex;
  std::vector<enzo::GridGroup> groups(r.grids.size());
  for (std::size_t n = 0; n < r.grids.size(); ++n) {
    const Grid& g = r.grids[n];
    const auto [at, added] = fileIndex.try_emplace(g.file, files.size());
    if (added) {
      files.push_back({r.dir / g.file, H5I_INVALID_HID});
      tried.push_back(false);
    }
    const std::size_t file = at->second;
    const bool visited = cells.wanted[n] || !r.sink.skipsPieces();
    if (visited && !tried[file]) {
      tried[file] = true;
      try {
        auto open = r.files.find(g.file);
        if (open == r.files.end() && present(files[file].path))
          open = r.files.emplace(g.file, openHdf5(files[file].path)).first;
        if (open != r.files.end()) files[file].id = open->second.get();
      } catch (const InputError&) {  // openGroup reports it where the grids' order meets it
      }
    }
    groups[n] = {file, fmt::format("/Grid{:08d}", g.id),
                 cells.wanted[n] && !r.sink.values(0).empty()};
  }
  return enzo::findGridDatasets(files, groups, r.channels);
}

// The values of the grids read, each channel's: a grid whose zones are its cells, one to one,
// straight into them; any other into `staged` (channel after channel), to be spread over its
// cells by placeCells.
void readValues(GridReading& r, const GridCells& cells, std::vector<std::vector<float>>& staged) {
  const std::vector<enzo::GridDatasets> found = findDatasets(r, cells);
  enzo::FieldReads fields(r.channels);
  std::vector<float*> into(r.channels.size());
  for (std::size_t n = 0; n < r.grids.size(); ++n) {
    const Grid& g = r.grids[n];
    if (!cells.wanted[n] && r.sink.skipsPieces()) continue;
    Handle group;  // a grid's file and group must be there, read or not
    if (!found[n].groupFound) group = openGroup(r, g);
    if (!cells.wanted[n] || r.sink.values(0).empty()) continue;
    const std::size_t zones = cells.covered[n].size();
    const bool oneToOne = std::ranges::none_of(cells.covered[n], std::identity()) &&
                          (r.axes == 3 || r.slabCells == g.width);
    if (!oneToOne) staged[n].resize(zones * r.channels.size());
    for (std::size_t c = 0; c < r.channels.size(); ++c)
      into[c] = oneToOne ? r.sink.values(c).data() + cells.first[n] : staged[n].data() + c * zones;
    const std::string groupName = fmt::format("/Grid{:08d}", g.id);
    if (!found[n].channels.empty()) {
      fields.addInPlace(r.dir / g.file, groupName, g.dims, r.axes, into, found[n].channels,
                        found[n].fileBytes);
      continue;
    }
    if (!group.valid()) group = openGroup(r, g);
    fields.add(group.get(), r.dir / g.file, groupName, g.dims, r.axes, into);
  }
  fields.run();
}

// Places every grid's cells that no finer grid covers, on all cores (a second read: those of the
// grids it reads), with their staged values.
void placeCells(GridReading& r, const GridCells& cells,
                const std::vector<std::vector<float>>& staged) {
  tbb::parallel_for(std::size_t(0), r.grids.size(), [&](std::size_t n) {
    if (!cells.wanted[n] && r.sink.skipsPieces()) return;
    const Grid& g = r.grids[n];
    const auto level = static_cast<std::uint8_t>(r.finest - g.level);
    const int copies = r.axes == 2 ? r.slabCells / g.width : 1;
    const std::size_t zones = cells.covered[n].size();
    std::size_t index = 0, at = cells.first[n];
    for (int k = 0; k < g.dims.z; ++k)
      for (int j = 0; j < g.dims.y; ++j)
        for (int i = 0; i < g.dims.x; ++i, ++index) {
          if (cells.covered[n][index]) continue;
          for (int copy = 0; copy < copies; ++copy, ++at) {
            glm::ivec3 lower = g.lower + glm::ivec3(i, j, k) * g.width;
            if (r.axes == 2) lower.z = copy * g.width;
            r.sink.place(at, lower, level);
            for (std::size_t c = 0; !staged[n].empty() && c < r.channels.size(); ++c)
              r.sink.values(c)[at] = staged[n][c * zones + index];
          }
        }
  });
}

}  // namespace

bricks::AmrField readEnzo(const fs::path& file, const ValueWindow* window, WindowedRead* read) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const auto sib = findSiblings(file);
  GridTable gridTable = readGridTable(file, sib);
  std::vector<Grid>& grids = gridTable.grids;
  const fs::path& table = gridTable.table;

  std::optional<EnzoParameters> parameters;
  const Domain domain = readDomain(sib, gridTable, parameters);
  const glm::dvec3 finestDx = placeGrids(grids, domain, table);
  const int axes = domain.axes;
  const int slabCells = axes == 2 ? slabThickness(grids, table) : 1;

  CellSink sink(window, file.string(), read);
  const int finest = std::ranges::max(grids, {}, &Grid::level).level;
  GridReading reading{grids, table, sib.dir, finest, axes, slabCells, sink, {}, {}};

  const GridCells cells = gridCells(reading, window);
  if (read) {
    read->pieces += grids.size();
    read->piecesRead += std::size_t(std::count(cells.wanted.begin(), cells.wanted.end(), 1));
  }
  {
    const Handle first = openGroup(reading, grids.front());
    listChannels(reading, first.get(), sib.dir / grids.front().file,
                 fmt::format("/Grid{:08d}", grids.front().id));
  }
  sink.presize(cells.total);
  std::vector<std::vector<float>> staged(grids.size());
  readValues(reading, cells, staged);
  placeCells(reading, cells, staged);
  glm::dvec3 origin = domain.left;
  if (axes == 2) origin.z = -0.5 * slabCells * finestDx.z;  // the plane is z = 0
  const WorldTransform transform{origin, finestDx};
  if (const auto problem = unrepresentablePositions(transform, sink.lowers(), sink.levels()))
    throw InputError(table.string(), "the grids cannot be placed: " + *problem);
  bricks::AmrField field = sink.finish(transform);
  DatasetInfo info = readEnzoInfo(parameters ? &*parameters : nullptr, finest, axes);
  if (field.findChannel("Temperature")) info.units.emplace("Temperature", "K");  // Enzo writes K
  field.setInfo(std::move(info));
  return field;
}

fs::path enzoParameterFile(const fs::path& file) { return findSiblings(file).parameter; }

std::optional<fs::path> enzoCompanionOf(const fs::path& file) {
  const std::string name = file.filename().string();
  const std::size_t dot = name.find('.');
  if (dot == std::string::npos || dot == 0) return std::nullopt;
  const fs::path prefix = file.parent_path() / name.substr(0, dot);
  std::error_code error;
  if (!fs::is_regular_file(prefix.string() + ".hierarchy", error)) return std::nullopt;
  return prefix;
}

}  // namespace amrstream::formats
