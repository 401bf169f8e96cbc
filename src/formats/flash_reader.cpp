#include "flash_reader.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include "util/input_error.hpp"

namespace amrstream::formats {
namespace {

// Owns an HDF5 identifier and closes it with the matching H5?close.
class Handle {
 public:
  using Closer = herr_t (*)(hid_t);
  Handle() = default;
  Handle(hid_t id, Closer close) : id_(id), close_(close) {}
  Handle(Handle&& other) noexcept { *this = std::move(other); }
  Handle& operator=(Handle&& other) noexcept {
    if (this != &other) {
      reset();
      id_ = std::exchange(other.id_, H5I_INVALID_HID);
      close_ = other.close_;
    }
    return *this;
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  ~Handle() { reset(); }

  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }

 private:
  void reset() {
    if (id_ >= 0 && close_ != nullptr) close_(id_);
    id_ = H5I_INVALID_HID;
  }
  hid_t id_ = H5I_INVALID_HID;
  Closer close_ = nullptr;
};

template <typename T>
struct Array {
  std::vector<T> values;
  std::vector<hsize_t> dims;
};

class FlashFile {
 public:
  explicit FlashFile(const std::filesystem::path& path) : path_(path.string()) {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) fail("no such file");
    if (H5Fis_hdf5(path_.c_str()) <= 0) fail("not an HDF5 file (or truncated)");
    file_ = Handle(H5Fopen(path_.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
    if (!file_.valid()) fail("cannot open the HDF5 file (truncated or corrupt?)");
  }

  [[noreturn]] void fail(const std::string& problem) const { throw InputError(path_, problem); }
  [[noreturn]] void fail(const std::string& dataset, const std::string& problem) const {
    throw InputError(path_, fmt::format("dataset '{}': {}", dataset, problem));
  }

  bool has(const std::string& name) const {
    return H5Lexists(file_.get(), name.c_str(), H5P_DEFAULT) > 0;
  }

  Handle open(const std::string& name, const std::string& why = "") const {
    if (!has(name)) fail(name, "missing" + why);
    Handle set(H5Dopen2(file_.get(), name.c_str(), H5P_DEFAULT), H5Dclose);
    if (!set.valid()) fail(name, "cannot open");
    return set;
  }

  std::vector<hsize_t> dims(const std::string& name, const Handle& set) const {
    Handle space(H5Dget_space(set.get()), H5Sclose);
    if (!space.valid()) fail(name, "cannot read the dataspace");
    const int rank = H5Sget_simple_extent_ndims(space.get());
    if (rank < 0) fail(name, "cannot read the dataspace");
    std::vector<hsize_t> result(static_cast<std::size_t>(rank));
    if (rank > 0 && H5Sget_simple_extent_dims(space.get(), result.data(), nullptr) < 0)
      fail(name, "cannot read the dataspace");
    return result;
  }

  H5T_class_t typeClass(const std::string& name, const Handle& set, std::size_t* size) const {
    Handle type(H5Dget_type(set.get()), H5Tclose);
    if (!type.valid()) fail(name, "cannot read the datatype");
    if (size != nullptr) *size = H5Tget_size(type.get());
    return H5Tget_class(type.get());
  }

  // Reads a numeric dataset, converted by HDF5 to T (int, float or double).
  template <typename T>
  Array<T> read(const std::string& name, const std::string& why = "") const {
    Handle set = open(name, why);
    Array<T> result{{}, dims(name, set)};
    std::size_t size = 0;
    const H5T_class_t cls = typeClass(name, set, &size);
    hid_t memType;
    if constexpr (std::is_same_v<T, int>) {
      if (cls != H5T_INTEGER) fail(name, "expected an integer dataset");
      memType = H5T_NATIVE_INT;
    } else {
      if (cls != H5T_FLOAT || (size != 4 && size != 8))
        fail(name, fmt::format("expected float32 or float64 data, found class {} size {}",
                               static_cast<int>(cls), size));
      memType = std::is_same_v<T, float> ? H5T_NATIVE_FLOAT : H5T_NATIVE_DOUBLE;
    }
    const hsize_t count =
        std::accumulate(result.dims.begin(), result.dims.end(), hsize_t{1}, std::multiplies<>());
    result.values.resize(count);
    if (count > 0 &&
        H5Dread(set.get(), memType, H5S_ALL, H5S_ALL, H5P_DEFAULT, result.values.data()) < 0)
      fail(name, "cannot read the data");
    return result;
  }

  // Fixed-length strings, trimmed of blanks and NULs.
  std::vector<std::string> readStrings(const std::string& name) const {
    Handle set = open(name);
    const auto shape = dims(name, set);
    Handle fileType(H5Dget_type(set.get()), H5Tclose);
    if (!fileType.valid() || H5Tget_class(fileType.get()) != H5T_STRING)
      fail(name, "expected a string dataset");
    if (H5Tis_variable_str(fileType.get()) > 0)
      fail(name, "variable-length strings are not supported");
    const std::size_t width = H5Tget_size(fileType.get());
    const hsize_t count =
        std::accumulate(shape.begin(), shape.end(), hsize_t{1}, std::multiplies<>());
    Handle memType(H5Tcopy(H5T_C_S1), H5Tclose);
    if (!memType.valid() || H5Tset_size(memType.get(), width) < 0)
      fail(name, "cannot build the string type");
    std::vector<char> buffer(count * width + 1, '\0');
    if (count > 0 &&
        H5Dread(set.get(), memType.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, buffer.data()) < 0)
      fail(name, "cannot read the data");
    std::vector<std::string> result;
    for (hsize_t i = 0; i < count; ++i) {
      std::string s(buffer.data() + i * width, width);
      s.erase(std::find(s.begin(), s.end(), '\0'), s.end());
      const auto first = s.find_first_not_of(' ');
      const auto last = s.find_last_not_of(' ');
      result.push_back(first == std::string::npos ? "" : s.substr(first, last - first + 1));
    }
    return result;
  }

  // A {name, value} compound list such as `integer scalars`; empty when the dataset is absent.
  std::vector<std::pair<std::string, int>> readIntPairs(const std::string& name) const {
    if (!has(name)) return {};
    Handle set = open(name);
    const auto shape = dims(name, set);
    Handle fileType(H5Dget_type(set.get()), H5Tclose);
    if (!fileType.valid() || H5Tget_class(fileType.get()) != H5T_COMPOUND)
      fail(name, "expected a compound dataset of name/value pairs");
    const int nameIndex = H5Tget_member_index(fileType.get(), "name");
    if (nameIndex < 0 || H5Tget_member_index(fileType.get(), "value") < 0)
      fail(name, "expected compound members 'name' and 'value'");
    Handle nameType(H5Tget_member_type(fileType.get(), static_cast<unsigned>(nameIndex)), H5Tclose);
    if (!nameType.valid() || H5Tget_class(nameType.get()) != H5T_STRING ||
        H5Tis_variable_str(nameType.get()) > 0)
      fail(name, "member 'name' is not a fixed-length string");
    const std::size_t width = H5Tget_size(nameType.get());
    const hsize_t count =
        std::accumulate(shape.begin(), shape.end(), hsize_t{1}, std::multiplies<>());

    Handle nameMem(H5Tcopy(H5T_C_S1), H5Tclose);
    H5Tset_size(nameMem.get(), width);
    Handle namesOnly(H5Tcreate(H5T_COMPOUND, width), H5Tclose);
    Handle valuesOnly(H5Tcreate(H5T_COMPOUND, sizeof(int)), H5Tclose);
    if (!namesOnly.valid() || !valuesOnly.valid() ||
        H5Tinsert(namesOnly.get(), "name", 0, nameMem.get()) < 0 ||
        H5Tinsert(valuesOnly.get(), "value", 0, H5T_NATIVE_INT) < 0)
      fail(name, "cannot build the compound type");
    std::vector<char> names(count * width + 1, '\0');
    std::vector<int> values(count);
    if (count > 0 &&
        (H5Dread(set.get(), namesOnly.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, names.data()) < 0 ||
         H5Dread(set.get(), valuesOnly.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0))
      fail(name, "cannot read the data");
    std::vector<std::pair<std::string, int>> result;
    for (hsize_t i = 0; i < count; ++i) {
      std::string s(names.data() + i * width, width);
      s.erase(std::find(s.begin(), s.end(), '\0'), s.end());
      s.erase(s.find_last_not_of(' ') + 1);
      result.emplace_back(s, values[i]);
    }
    return result;
  }

  const std::string& path() const { return path_; }

 private:
  std::string path_;
  Handle file_;
};

std::string shapeText(const std::vector<hsize_t>& dims) {
  return fmt::format("[{}]", fmt::join(dims, ", "));
}

// nxb/nyb/nzb and dimensionality from `integer scalars`, else `integer runtime parameters`.
struct BlockShape {
  int n[3] = {0, 0, 0};
  int dimensionality = 0;
};

BlockShape readBlockShape(const FlashFile& file) {
  BlockShape shape;
  const char* keys[3] = {"nxb", "nyb", "nzb"};
  for (const char* list : {"integer runtime parameters", "integer scalars"}) {
    for (const auto& [key, value] : file.readIntPairs(list)) {
      for (int a = 0; a < 3; ++a)
        if (key == keys[a]) shape.n[a] = value;
      if (key == "dimensionality") shape.dimensionality = value;
    }
  }
  return shape;
}

struct Leaf {
  std::size_t block;
  int level;  // ours: 0 = finest
  glm::ivec3 lower;
};

}  // namespace

bricks::AmrField readFlash(const std::filesystem::path& path) {
  const FlashFile file(path);
  const auto names = file.readStrings("unknown names");
  if (names.empty()) file.fail("unknown names", "lists no variables");

  const auto refine = file.read<int>("refine level");
  const auto nodeType = file.read<int>("node type");
  const auto bbox = file.read<double>("bounding box");
  const auto blockSize = file.read<double>("block size");
  const std::size_t nb = refine.dims.empty() ? 0 : refine.dims[0];
  if (refine.dims.size() != 1 || nb == 0)
    file.fail("refine level", fmt::format("shape {} is not [nblocks]", shapeText(refine.dims)));
  if (nodeType.dims != std::vector<hsize_t>{nb})
    file.fail("node type", fmt::format("shape {} is not [{}]", shapeText(nodeType.dims), nb));
  if (bbox.dims != std::vector<hsize_t>{nb, 3, 2})
    file.fail("bounding box", fmt::format("shape {} is not [{}, 3, 2]", shapeText(bbox.dims), nb));
  if (blockSize.dims != std::vector<hsize_t>{nb, 3})
    file.fail("block size", fmt::format("shape {} is not [{}, 3]", shapeText(blockSize.dims), nb));

  // Cells per block: the parameters when present, else the first variable's shape.
  BlockShape shape = readBlockShape(file);
  {
    const std::string& first = names.front();
    const Handle set = file.open(first, " (listed in 'unknown names')");
    const auto d = file.dims(first, set);
    if (d.size() != 4 || d[0] != nb)
      file.fail(first, fmt::format("shape {} is not [{}, nzb, nyb, nxb]", shapeText(d), nb));
    for (int a = 0; a < 3; ++a)
      if (shape.n[a] == 0) shape.n[a] = static_cast<int>(d[3 - a]);
  }
  for (int a = 0; a < 3; ++a)
    if (shape.n[a] < 1 || shape.n[a] > 4096)
      file.fail(fmt::format("cells per block along axis {} is {}", a, shape.n[a]));
  if (shape.dimensionality == 0) shape.dimensionality = shape.n[2] == 1 ? 2 : 3;
  if (shape.dimensionality == 1 || shape.n[1] == 1) file.fail("1D FLASH files are not supported");
  if (shape.dimensionality != 2 && shape.dimensionality != 3)
    file.fail(fmt::format("dimensionality {} is not 2 or 3", shape.dimensionality));
  if (shape.dimensionality == 2 && shape.n[2] != 1)
    file.fail(fmt::format("2D file with nzb = {} (expected 1)", shape.n[2]));
  const int axes = shape.dimensionality;

  // Leaves, finest refine level, finest cell size and domain lower corner.
  std::vector<std::size_t> leafBlocks;
  int rmax = 0;
  glm::dvec3 dxf(std::numeric_limits<double>::infinity());
  glm::dvec3 domainLo(std::numeric_limits<double>::infinity());
  const auto lo = [&](std::size_t b, int a) { return bbox.values[b * 6 + a * 2]; };
  const auto hi = [&](std::size_t b, int a) { return bbox.values[b * 6 + a * 2 + 1]; };
  for (std::size_t b = 0; b < nb; ++b) {
    if (nodeType.values[b] != 1) continue;
    leafBlocks.push_back(b);
    if (refine.values[b] < 1)
      file.fail("refine level", fmt::format("block {} has refine level {}", b, refine.values[b]));
    rmax = std::max(rmax, refine.values[b]);
    for (int a = 0; a < 3; ++a) {
      const double extent = hi(b, a) - lo(b, a);
      if (!std::isfinite(lo(b, a)) || !std::isfinite(hi(b, a)) || (a < axes && !(extent > 0)))
        file.fail("bounding box",
                  fmt::format("block {} axis {} spans [{}, {}]", b, a, lo(b, a), hi(b, a)));
      const double size = blockSize.values[b * 3 + a];
      if (a < axes && !(std::abs(size - extent) <= 1e-4 * std::abs(extent)))
        file.fail("block size", fmt::format("block {} axis {}: size {} but bounding box extent {}",
                                            b, a, size, extent));
      domainLo[a] = std::min(domainLo[a], lo(b, a));
      if (a < axes) dxf[a] = std::min(dxf[a], extent / shape.n[a]);
    }
  }
  if (leafBlocks.empty()) file.fail("node type", "no leaf blocks (node type 1)");
  if (rmax - 1 > bricks::kMaxLevel)
    file.fail("refine level",
              fmt::format("{} refine levels exceed the supported {}", rmax, bricks::kMaxLevel + 1));
  // The bounding boxes carry rounding noise: spread the domain evenly over its finest cells.
  for (int a = 0; a < axes; ++a) {
    double domainHi = -std::numeric_limits<double>::infinity();
    for (std::size_t b : leafBlocks) domainHi = std::max(domainHi, hi(b, a));
    const double cells = std::round((domainHi - domainLo[a]) / dxf[a]);
    if (cells >= 1 && cells <= std::ldexp(1.0, bricks::kMaxExtentBits))
      dxf[a] = (domainHi - domainLo[a]) / cells;
  }
  if (axes == 2) dxf.z = dxf.x;

  // Block placement in finest-cell units; checks that every block's cells are 2^L cubes.
  std::vector<Leaf> leaves;
  int coarsest = 0;
  for (std::size_t b : leafBlocks) {
    Leaf leaf{b, rmax - refine.values[b], glm::ivec3(0)};
    const double width = std::ldexp(1.0, leaf.level);
    for (int a = 0; a < axes; ++a) {
      const double cellWidth = (hi(b, a) - lo(b, a)) / shape.n[a] / dxf[a];
      if (std::abs(cellWidth - width) > 1e-3 * width)
        file.fail("bounding box",
                  fmt::format("block {} at refine level {} has cells {} finest cells wide along "
                              "axis {}, expected {}",
                              b, refine.values[b], cellWidth, a, width));
      const double corner = (lo(b, a) - domainLo[a]) / dxf[a];
      if (corner + shape.n[a] * width > std::ldexp(1.0, bricks::kMaxExtentBits))
        file.fail("bounding box", fmt::format("block {} ends beyond 2^{} finest cells along "
                                              "axis {}",
                                              b, bricks::kMaxExtentBits, a));
      if (std::abs(corner - std::round(corner)) > 1e-3)
        file.fail("bounding box", fmt::format("block {} lower corner {} along axis {} is not on "
                                              "the finest grid",
                                              b, lo(b, a), a));
      leaf.lower[a] = static_cast<int>(std::lround(corner));
    }
    coarsest = std::max(coarsest, leaf.level);
    leaves.push_back(leaf);
  }

  // Cells in block order, z-y-x within a block (the datasets' [nb][nzb][nyb][nxb] order).
  const std::size_t perBlock = static_cast<std::size_t>(shape.n[0]) * shape.n[1] * shape.n[2];
  std::size_t total = 0;
  for (const Leaf& leaf : leaves) total += perBlock << (axes == 2 ? coarsest - leaf.level : 0);
  if (total > (std::size_t{1} << 31))
    file.fail(
        fmt::format("{} cells after stacking 2D cells into a uniform slab is too many", total));
  std::vector<glm::ivec3> lowers;
  std::vector<std::uint8_t> levels;
  std::vector<std::size_t> source;  // index into a variable's data
  lowers.reserve(total);
  levels.reserve(total);
  source.reserve(total);
  for (const Leaf& leaf : leaves) {
    const int w = 1 << leaf.level;
    const int copies = axes == 2 ? 1 << (coarsest - leaf.level) : 1;
    for (int k = 0; k < shape.n[2]; ++k)
      for (int j = 0; j < shape.n[1]; ++j)
        for (int i = 0; i < shape.n[0]; ++i) {
          const std::size_t from = leaf.block * perBlock +
                                   (static_cast<std::size_t>(k) * shape.n[1] + j) * shape.n[0] + i;
          for (int c = 0; c < copies; ++c) {
            const int z = axes == 2 ? c * w : leaf.lower.z + k * w;
            lowers.emplace_back(leaf.lower.x + i * w, leaf.lower.y + j * w, z);
            levels.push_back(static_cast<std::uint8_t>(leaf.level));
            source.push_back(from);
          }
        }
  }

  std::vector<bricks::Channel> channels;
  const std::vector<hsize_t> expected{nb, static_cast<hsize_t>(shape.n[2]),
                                      static_cast<hsize_t>(shape.n[1]),
                                      static_cast<hsize_t>(shape.n[0])};
  for (const std::string& name : names) {
    const auto data = file.read<double>(name, " (listed in 'unknown names')");
    if (data.dims != expected)
      file.fail(name, fmt::format("shape {} is not [nblocks, nzb, nyb, nxb] = {}",
                                  shapeText(data.dims), shapeText(expected)));
    bricks::Channel channel{name, std::vector<float>(source.size())};
    for (std::size_t c = 0; c < source.size(); ++c) {
      const double v = data.values[source[c]];
      if (std::isfinite(v) && std::abs(v) > std::numeric_limits<float>::max())
        file.fail(name, fmt::format("value {} in block {} exceeds the float range", v,
                                    source[c] / perBlock));
      channel.values[c] = static_cast<float>(v);
    }
    channels.push_back(std::move(channel));
  }

  return bricks::AmrField(std::move(lowers), std::move(levels), std::move(channels),
                          bricks::WorldTransform{domainLo, dxf}, path.string());
}

}  // namespace amrstream::formats
