#include "formats/enzo_reader.hpp"

#include <fmt/format.h>
#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "enzo_info.hpp"
#include "enzo_parameters.hpp"
#include "util/input_error.hpp"

namespace amrstream::formats {
namespace {

namespace fs = std::filesystem;

// Owns one hid_t and closes it with the matching H5?close.
class Handle {
 public:
  Handle(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  Handle(Handle&& o) noexcept : id_(std::exchange(o.id_, H5I_INVALID_HID)), close_(o.close_) {}
  Handle& operator=(Handle&&) = delete;
  Handle(const Handle&) = delete;
  ~Handle() {
    if (id_ >= 0) close_(id_);
  }
  hid_t get() const { return id_; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

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
  bool known = false;
};

std::string trim(std::string s) {
  const auto* ws = " \t\r\n";
  s.erase(0, s.find_first_not_of(ws));
  s.erase(s.find_last_not_of(ws) + 1);
  return s;
}

template <typename T>
glm::vec<3, T> parse3(const std::string& value, const fs::path& file, const std::string& what) {
  std::istringstream in(value);
  glm::vec<3, T> v{};
  std::string extra;
  if (!(in >> v.x >> v.y >> v.z) || (in >> extra))
    throw InputError(file.string(), fmt::format("{} needs 3 numbers, got '{}'", what, value));
  return v;
}

Domain readParameters(const EnzoParameters& parameters) {
  const auto& kv = parameters.values();
  const fs::path& file = parameters.file();
  auto need = [&](const char* key) -> const std::string& {
    const auto it = kv.find(key);
    if (it == kv.end()) throw InputError(file.string(), fmt::format("missing {}", key));
    return it->second;
  };
  Domain d;
  d.topDims = parse3<int>(need("TopGridDimensions"), file, "TopGridDimensions");
  d.left = parse3<double>(need("DomainLeftEdge"), file, "DomainLeftEdge");
  d.right = parse3<double>(need("DomainRightEdge"), file, "DomainRightEdge");
  if (const auto it = kv.find("RefineBy"); it != kv.end() && std::stoi(it->second) != 2)
    throw InputError(file.string(),
                     fmt::format("RefineBy {} is not supported (only 2)", it->second));
  if (kv.contains("TopGridRank") && need("TopGridRank") != "3")
    throw InputError(file.string(), "only 3D data (TopGridRank 3) is supported");
  d.known = true;
  return d;
}

// The text hierarchy: blocks `Grid = N` of `Key = value` lines, then `Pointer:` lines.
std::vector<Grid> readHierarchy(const fs::path& file) {
  std::ifstream in(file);
  if (!in) throw InputError(file.string(), "cannot open the hierarchy file");
  std::vector<std::map<std::string, std::string>> blocks;
  std::set<std::pair<int, std::string>> pointers;  // (grid, ThisLevel/NextLevel)
  int maxTarget = 0;
  for (std::string line; std::getline(in, line);) {
    const auto eq = line.find('=');
    if (eq == std::string::npos) continue;
    const auto key = trim(line.substr(0, eq));
    const auto value = trim(line.substr(eq + 1));
    if (key == "Grid") {
      if (value != std::to_string(blocks.size() + 1))
        throw InputError(file.string(), fmt::format("expected Grid = {}, got Grid = {}",
                                                    blocks.size() + 1, value));
      blocks.emplace_back();
    } else if (key.starts_with("Pointer:")) {
      // Pointer: Grid[a]->NextGridThisLevel = b
      int a = 0;
      char which[32] = {};
      int target = -1;
      if (std::sscanf(key.c_str(), "Pointer: Grid[%d]->NextGrid%31s", &a, which) != 2 ||
          std::sscanf(value.c_str(), "%d", &target) != 1)
        throw InputError(file.string(), fmt::format("cannot parse '{}' (truncated?)", trim(line)));
      pointers.emplace(a, which);
      maxTarget = std::max(maxTarget, target);
    } else if (!blocks.empty()) {
      blocks.back()[key] = value;
    }
  }
  const int n = static_cast<int>(blocks.size());
  if (n == 0) throw InputError(file.string(), "no grids (no `Grid = 1` line)");
  if (maxTarget > n)
    throw InputError(
        file.string(),
        fmt::format("a pointer names grid {} but only {} grids are listed (truncated?)", maxTarget,
                    n));
  std::vector<Grid> grids;
  for (int i = 0; i < n; ++i) {
    const auto& b = blocks[i];
    auto need = [&](const char* key) -> const std::string& {
      const auto it = b.find(key);
      if (it == b.end())
        throw InputError(file.string(), fmt::format("grid {} lacks {} (truncated?)", i + 1, key));
      return it->second;
    };
    for (const char* which : {"ThisLevel", "NextLevel"})
      if (!pointers.contains({i + 1, which}))
        throw InputError(
            file.string(),
            fmt::format("grid {} lacks its NextGrid{} pointer (truncated?)", i + 1, which));
    if (trim(need("GridRank")) != "3")
      throw InputError(file.string(), fmt::format("grid {}: only GridRank 3 is supported", i + 1));
    Grid g;
    g.id = i + 1;
    const auto start = parse3<int>(need("GridStartIndex"), file, "GridStartIndex");
    const auto end = parse3<int>(need("GridEndIndex"), file, "GridEndIndex");
    const auto total = parse3<int>(need("GridDimension"), file, "GridDimension");
    g.dims = end - start + 1;
    if (glm::any(glm::lessThan(start, glm::ivec3(0))) ||
        glm::any(glm::greaterThanEqual(end, total)))
      throw InputError(file.string(),
                       fmt::format("grid {}: start/end index outside GridDimension", g.id));
    g.left = parse3<double>(need("GridLeftEdge"), file, "GridLeftEdge");
    g.right = parse3<double>(need("GridRightEdge"), file, "GridRightEdge");
    if (const auto it = b.find("Level"); it != b.end()) g.level = std::stoi(it->second);
    // An absolute path from the machine that wrote it: only the basename is meaningful.
    g.file = fs::path(need("BaryonFileName")).filename().string();
    grids.push_back(g);
  }
  return grids;
}

std::vector<hsize_t> shapeOf(hid_t dataset, const fs::path& file, const std::string& name) {
  const auto space = checked(H5Dget_space(dataset), H5Sclose, file, "get the shape of " + name);
  const int rank = H5Sget_simple_extent_ndims(space.get());
  if (rank < 0)
    throw InputError(file.string(), fmt::format("HDF5 could not get the rank of {}", name));
  std::vector<hsize_t> dims(rank);
  H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
  return dims;
}

template <typename T>
std::vector<T> readTable(hid_t h5file, const fs::path& file, const char* name, hid_t memType,
                         std::vector<hsize_t> expected) {
  const auto ds = checked(H5Dopen2(h5file, name, H5P_DEFAULT), H5Dclose, file,
                          fmt::format("open dataset {}", name));
  if (shapeOf(ds.get(), file, name) != expected)
    throw InputError(file.string(), fmt::format("dataset {} has an unexpected shape", name));
  std::size_t count = 1;
  for (auto e : expected) count *= e;
  std::vector<T> values(count);
  if (H5Dread(ds.get(), memType, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0)
    throw InputError(file.string(), fmt::format("HDF5 could not read dataset {}", name));
  return values;
}

// The HDF5 grid table: LeftEdges, RightEdges, ActiveDimensions (n,3, x y z), Level (n).
std::vector<Grid> readHarrays(const fs::path& file) {
  const auto h5 =
      checked(H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, file, "open the file");
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
    g.dims = {dims[3 * i], dims[3 * i + 1], dims[3 * i + 2]};
  }
  return grids;
}

// Sets level (checked against the cell size), lower and width of every grid; returns the finest dx.
glm::dvec3 placeGrids(std::vector<Grid>& grids, const Domain& domain, const fs::path& table) {
  const auto src = table.string();
  const glm::dvec3 topDx = (domain.right - domain.left) / glm::dvec3(domain.topDims);
  if (glm::any(glm::lessThanEqual(topDx, glm::dvec3(0.0))))
    throw InputError(src, "the domain or the top grid dimensions are empty");
  int finest = 0;
  for (auto& g : grids) {
    if (glm::any(glm::lessThanEqual(g.dims, glm::ivec3(0))))
      throw InputError(src, fmt::format("grid {} has no active zones", g.id));
    const glm::dvec3 ratio = topDx * glm::dvec3(g.dims) / (g.right - g.left);
    const int level = static_cast<int>(std::lround(std::log2(ratio.x)));
    for (int a = 0; a < 3; ++a)
      if (!(std::abs(ratio[a] / std::ldexp(1.0, level) - 1.0) < 1e-6))
        throw InputError(src, fmt::format("grid {}: cell size is not the top-grid cell size / 2^L "
                                          "(edges and dimensions disagree)",
                                          g.id));
    if (g.level >= 0 && g.level != level)
      throw InputError(
          src, fmt::format("grid {}: Level {} but its cell size says {}", g.id, g.level, level));
    if (level < 0 || level > bricks::kMaxLevel)
      throw InputError(src, fmt::format("grid {}: level {} out of range", g.id, level));
    g.level = level;
    finest = std::max(finest, level);
  }
  const glm::dvec3 finestDx = topDx / std::ldexp(1.0, finest);
  for (auto& g : grids) {
    g.width = 1 << (finest - g.level);
    const glm::dvec3 lo = (g.left - domain.left) / finestDx;
    const glm::dvec3 hi = (g.right - domain.left) / finestDx;
    for (int a = 0; a < 3; ++a) {
      g.lower[a] = static_cast<int>(std::lround(lo[a]));
      const double up = static_cast<double>(g.lower[a]) + double(g.dims[a]) * g.width;
      if (std::abs(lo[a] - g.lower[a]) > 1e-3 || std::abs(hi[a] - up) > 1e-3 ||
          g.lower[a] % g.width != 0)
        throw InputError(src, fmt::format("grid {} is not aligned to its level's cells", g.id));
    }
  }
  return finestDx;
}

// Marks the cells of `g` covered by grids one level finer. Those align with g's cells; deeper grids
// nest inside them (a violation shows up as an overlap in AmrField).
std::vector<bool> coveredCells(const Grid& g, const std::vector<Grid>& grids,
                               const fs::path& table) {
  const glm::ivec3 n = g.dims;
  std::vector<bool> covered(std::size_t(n.x) * n.y * n.z, false);
  const glm::ivec3 gUpper = g.lower + n * g.width;
  for (const auto& h : grids) {
    if (h.level != g.level + 1) continue;
    const glm::ivec3 lo = glm::max(g.lower, h.lower) - g.lower;
    const glm::ivec3 hi = glm::min(gUpper, h.lower + h.dims * h.width) - g.lower;
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

std::vector<float> readField(hid_t group, const fs::path& file, const std::string& groupName,
                             const std::string& name, glm::ivec3 dims) {
  const auto what = fmt::format("{}/{}", groupName, name);
  if (H5Lexists(group, name.c_str(), H5P_DEFAULT) <= 0)
    throw InputError(file.string(), fmt::format("dataset {} is missing", what));
  const auto ds = checked(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose, file,
                          fmt::format("open dataset {}", what));
  const std::vector<hsize_t> expected{hsize_t(dims.z), hsize_t(dims.y), hsize_t(dims.x)};
  const auto shape = shapeOf(ds.get(), file, what);
  if (shape != expected) {
    std::string got;
    for (auto s : shape) got += fmt::format("{}{}", got.empty() ? "" : ",", s);
    throw InputError(file.string(), fmt::format("dataset {} has shape ({}), expected ({},{},{}) "
                                                "= (nz,ny,nx) active zones",
                                                what, got, dims.z, dims.y, dims.x));
  }
  const auto type = checked(H5Dget_type(ds.get()), H5Tclose, file, "get the type of " + what);
  if (H5Tget_class(type.get()) != H5T_FLOAT)
    throw InputError(file.string(), fmt::format("dataset {} is not floating point", what));
  std::vector<float> values(std::size_t(dims.x) * dims.y * dims.z);
  if (H5Dread(ds.get(), H5T_NATIVE_FLOAT, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0)
    throw InputError(file.string(), fmt::format("HDF5 could not read dataset {}", what));
  return values;
}

struct Siblings {
  fs::path dir, parameter, hierarchy, harrays;
};

Siblings findSiblings(const fs::path& file) {
  std::error_code ec;
  if (!fs::is_regular_file(file, ec)) throw InputError(file.string(), "no such file");
  fs::path base = file;
  const auto ext = file.extension().string();
  if (ext == ".hierarchy" || ext == ".harrays" || ext.starts_with(".cpu")) base.replace_extension();
  Siblings s;
  s.dir = file.parent_path();
  s.parameter = base;
  s.hierarchy = base.string() + ".hierarchy";
  s.harrays = base.string() + ".harrays";
  return s;
}

}  // namespace

bricks::AmrField readEnzo(const fs::path& file) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const auto sib = findSiblings(file);
  std::error_code ec;
  const bool hasHierarchy = fs::is_regular_file(sib.hierarchy, ec);
  const bool hasHarrays = fs::is_regular_file(sib.harrays, ec);
  if (!hasHierarchy && !hasHarrays)
    throw InputError(file.string(),
                     fmt::format("neither {} nor {} exists", sib.hierarchy.filename().string(),
                                 sib.harrays.filename().string()));

  std::vector<Grid> grids;
  fs::path table;
  std::vector<Grid> text;
  if (hasHierarchy) text = readHierarchy(sib.hierarchy);
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

  Domain domain;
  std::optional<EnzoParameters> parameters;
  if (fs::is_regular_file(sib.parameter, ec)) {
    parameters.emplace(sib.parameter);
    domain = readParameters(*parameters);
  } else {
    // Without the parameter file, the first grid is the root grid spanning the domain.
    domain.left = grids[0].left;
    domain.right = grids[0].right;
    domain.topDims = grids[0].dims;
  }
  const glm::dvec3 finestDx = placeGrids(grids, domain, table);

  std::vector<glm::ivec3> lowers;
  std::vector<std::uint8_t> levels;
  std::vector<bricks::Channel> channels;
  std::map<std::string, Handle> files;
  const int finest = std::ranges::max(grids, {}, &Grid::level).level;

  for (const auto& g : grids) {
    const fs::path path = sib.dir / g.file;
    auto it = files.find(g.file);
    if (it == files.end()) {
      if (!fs::is_regular_file(path, ec))
        throw InputError(path.string(), fmt::format("grid {}'s field file is missing", g.id));
      it = files
               .emplace(g.file, checked(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT),
                                        H5Fclose, path, "open the file"))
               .first;
    }
    const auto groupName = fmt::format("/Grid{:08d}", g.id);
    const auto group = checked(H5Gopen2(it->second.get(), groupName.c_str(), H5P_DEFAULT), H5Gclose,
                               path, fmt::format("open group {}", groupName));
    if (channels.empty()) {
      std::vector<std::string> names;
      if (H5Literate(group.get(), H5_INDEX_NAME, H5_ITER_INC, nullptr, collectName, &names) < 0)
        throw InputError(path.string(), fmt::format("HDF5 could not list group {}", groupName));
      for (auto& name : names)
        if (!name.starts_with("particle_")) channels.push_back({name, {}});
      if (channels.empty())
        throw InputError(path.string(), fmt::format("group {} has no field datasets", groupName));
    }
    const auto covered = coveredCells(g, grids, table);
    std::vector<std::vector<float>> fields;
    for (const auto& c : channels)
      fields.push_back(readField(group.get(), path, groupName, c.name, g.dims));

    const auto level = static_cast<std::uint8_t>(finest - g.level);
    std::size_t index = 0;
    for (int k = 0; k < g.dims.z; ++k)
      for (int j = 0; j < g.dims.y; ++j)
        for (int i = 0; i < g.dims.x; ++i, ++index) {
          if (covered[index]) continue;
          lowers.push_back(g.lower + glm::ivec3(i, j, k) * g.width);
          levels.push_back(level);
          for (std::size_t c = 0; c < channels.size(); ++c)
            channels[c].values.push_back(fields[c][index]);
        }
  }
  bricks::AmrField field(std::move(lowers), std::move(levels), std::move(channels),
                         bricks::WorldTransform{domain.left, finestDx}, file.string());
  field.setInfo(readEnzoInfo(parameters ? &*parameters : nullptr, finest));
  return field;
}

fs::path enzoParameterFile(const fs::path& file) { return findSiblings(file).parameter; }

}  // namespace amrstream::formats
