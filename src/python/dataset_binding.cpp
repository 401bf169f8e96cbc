// amrstream.Dataset, amrstream.Field, load, from_arrays.

#include <fmt/format.h>
#include <pybind11/stl.h>

#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <string>

#include "amrstream/builtin.hpp"
#include "amrstream/dataset.hpp"
#include "amrstream/error.hpp"
#include "amrstream/field.hpp"
#include "api/handles.hpp"
#include "bindings.hpp"
#include "flow/seeds.hpp"
#include "flow/uniform_resample.hpp"
#include "numpy_views.hpp"
#include "setting_args.hpp"

namespace amrstream::python {

namespace {

py::tuple tuple3(glm::dvec3 v) { return py::make_tuple(v.x, v.y, v.z); }

py::object periodicOf(const DatasetInfo& info) {
  if (!info.periodicKnown) return py::none();
  return py::make_tuple(info.periodic[0], info.periodic[1], info.periodic[2]);
}

// Field.resample's dims: one count or three, whole numbers (the library checks their range).
std::vector<std::uint64_t> gridCounts(py::handle dims) {
  constexpr std::uint64_t most = std::numeric_limits<std::uint64_t>::max();
  if (!PySequence_Check(dims.ptr()) || PyUnicode_Check(dims.ptr()))
    return {wholeNumberIn<std::uint64_t>("dims", dims, 0, most)};
  std::vector<std::uint64_t> counts;
  for (const py::object& count : detail::items("dims", dims, 0))
    counts.push_back(wholeNumberIn<std::uint64_t>("dims", count, 0, most));
  return counts;
}

// Field.resample's box, as the command line's --box: finite numbers a float holds.
std::vector<double> resampleBox(py::handle box) {
  std::vector<double> bounds;
  if (box.is_none()) return bounds;
  for (const py::object& bound : detail::items("box", box, 6))
    bounds.push_back(realIn("box", bound, -settings::kFloatMax, settings::kFloatMax));
  return bounds;
}

// Field.resample: the grid's arrays indexed [i, j, k] (x first, as yt's covering grids), views
// over one grid that the returned arrays keep alive.
py::dict resampled(const Field& p, py::object dims, Given<std::optional<std::vector<double>>> box) {
  const flow::VectorVolume& volume = volumeOf(p);
  const flow::UniformGridSpec spec =
      flow::uniformGridSpec(volume, gridCounts(dims), resampleBox(box.value));
  auto grid = std::make_shared<flow::UniformGrid>();
  {
    py::gil_scoped_release unlocked;
    *grid = flow::resampleUniform(volume, spec);
  }
  const py::capsule owner(new std::shared_ptr<flow::UniformGrid>(grid), [](void* g) {
    delete static_cast<std::shared_ptr<flow::UniformGrid>*>(g);
  });
  const auto nx = py::ssize_t(spec.dims[0]), ny = py::ssize_t(spec.dims[1]),
             nz = py::ssize_t(spec.dims[2]);
  const std::size_t channels = volume.channelCount();
  const auto strides = [&](py::ssize_t bytes) {  // of point (i, j, k), `bytes` per point
    return std::vector<py::ssize_t>{bytes, bytes * nx, bytes * nx * ny};
  };
  py::dict out;
  out["origin"] = tuple3(spec.origin());
  out["spacing"] = tuple3(spec.spacing());
  out["dims"] = py::make_tuple(nx, ny, nz);
  std::vector<py::ssize_t> vectorStrides = strides(sizeof(glm::vec3));
  vectorStrides.push_back(sizeof(float));
  out[py::str(volume.vectorName)] = readOnly(
      py::array_t<float>({nx, ny, nz, py::ssize_t(3)}, vectorStrides, &grid->vectors[0].x, owner));
  for (std::size_t c = 0; c < channels; ++c)
    out[py::str(volume.channelNames[c])] =
        readOnly(py::array_t<float>({nx, ny, nz}, strides(py::ssize_t(channels * sizeof(float))),
                                    grid->channels.data() + c, owner));
  out["valid"] = readOnly(py::array_t<bool>(
      {nx, ny, nz}, strides(1), reinterpret_cast<const bool*>(grid->valid.data()), owner));
  return out;
}

// The file's level of every cell, as the file numbers its levels.
py::array fileLevels(const Dataset& d) {
  py::array_t<std::int32_t> levels(py::ssize_t(d.cellCount()));
  auto out = levels.mutable_unchecked<1>();
  const std::span<const std::uint8_t> internal = d.levels();
  for (std::size_t i = 0; i < internal.size(); ++i)
    out(py::ssize_t(i)) = d.info().fileLevel(internal[i]);
  return levels;
}

// origin or finest_width: 3 finite numbers (fromCells checks what else they must be).
glm::dvec3 vec3Of(py::handle value, const char* what) {
  const std::vector<py::object> given = detail::items(what, value, 3);
  constexpr double most = std::numeric_limits<double>::max();
  glm::dvec3 v;
  for (int a = 0; a < 3; ++a) v[a] = realIn(what, given[std::size_t(a)], -most, most);
  return v;
}

// `value` as a numpy array (an array as it is, without a copy) of `rank` dimensions whose items
// are real numbers, checked before anything is converted: ValueError "`what` must be `shape`".
py::array realArray(py::handle value, const std::string& what, const std::string& shape, int rank) {
  const py::array array = py::array::ensure(value);
  if (!array || array.ndim() != rank)
    throw py::value_error(fmt::format("{} must be {}", what, shape));
  if (!holdsRealNumbers(array))
    throw py::value_error(fmt::format("{} must hold real numbers, not {}", what, itemsOf(array)));
  return array;
}

// Corners and levels given as floats must be whole numbers.
void requireWholeNumbers(const py::array& array, const std::string& what) {
  if (array.dtype().kind() != 'f') return;
  const auto real = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(array);
  for (py::ssize_t i = 0; i < real.size(); ++i)
    if (real.data()[i] != std::floor(real.data()[i]))
      throw py::value_error(
          fmt::format("{} must be whole numbers; element {} is {}", what, i, real.data()[i]));
}

// More cells than a dataset may number, or than this machine can hold, are refused before any is
// converted: a broadcast array of many rows takes no memory until it is copied.
void checkCellCount(std::size_t cells) {
  if (cells > kMaxBuiltinCells)
    throw settingError("corners", fmt::format("{} cells are more than the {} a dataset may hold "
                                              "(cells are numbered in 32 bits)",
                                              cells, kMaxBuiltinCells));
  checkGeneratedCells(double(cells), "corners");
}

std::vector<glm::ivec3> cornersOf(const py::array& given) {
  requireWholeNumbers(given, "corners (in finest cells)");
  const auto c =
      py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(given);
  const std::int64_t limit = std::int64_t(1) << bricks::kMaxExtentBits;
  std::vector<glm::ivec3> corners(std::size_t(c.shape(0)));
  const std::int64_t* values = c.data();
  for (std::size_t i = 0; i < corners.size(); ++i)
    for (int a = 0; a < 3; ++a) {
      const std::int64_t v = values[3 * i + std::size_t(a)];
      if (v < -limit || v > limit)
        throw settingError("corners", fmt::format("corner {} of cell {} is {}, outside the range "
                                                  "{} to {}",
                                                  "xyz"[a], i, v, -limit, limit));
      corners[i][a] = int(v);
    }
  return corners;
}

// Levels count up from the coarsest, 0: none may be finer than the library resolves.
std::vector<int> levelsOf(const py::array& given) {
  requireWholeNumbers(given, "levels");
  const auto l =
      py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(given);
  std::vector<int> levels(std::size_t(l.shape(0)));
  for (std::size_t i = 0; i < levels.size(); ++i) {
    const std::int64_t level = l.data()[i];
    if (level < 0 || level > bricks::kMaxLevel)
      throw settingError("levels", fmt::format("level {} of cell {} is outside the range 0 to {}",
                                               level, i, bricks::kMaxLevel));
    levels[i] = int(level);
  }
  return levels;
}

Channel channelOf(py::handle key, py::handle values, std::size_t cells) {
  const std::string name = py::str(key);
  const std::string shape = fmt::format("an (N,) array of {} values", cells);
  const py::array given = realArray(values, fmt::format("field '{}'", name), shape, 1);
  if (std::size_t(given.shape(0)) != cells)
    throw py::value_error(fmt::format("field '{}' must be {}", name, shape));
  const auto v = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(given);
  return {name, std::vector<float>(v.data(), v.data() + cells)};
}

std::shared_ptr<Dataset> fromArrays(py::handle corners, py::handle levels, py::dict fields,
                                    py::handle origin, py::handle finestWidth,
                                    std::optional<std::array<bool, 3>> periodic,
                                    Given<std::optional<double>> time, std::string timeUnit,
                                    std::string lengthUnit, std::optional<double> lengthUnitCm,
                                    std::string source, std::string format,
                                    std::optional<std::map<std::string, std::string>> units,
                                    int dimensions) {
  const py::array givenCorners =
      realArray(corners, "corners", "an (N, 3) array of integer cell indices", 2);
  if (givenCorners.shape(1) != 3)
    throw py::value_error("corners must be an (N, 3) array of integer cell indices");
  const std::size_t n = std::size_t(givenCorners.shape(0));
  const py::array givenLevels = realArray(
      levels, "levels", fmt::format("an (N,) array with one level per corner ({} corners)", n), 1);
  if (std::size_t(givenLevels.shape(0)) != n)
    throw py::value_error(
        fmt::format("levels must be an (N,) array with one level per corner ({} corners)", n));
  checkCellCount(n);
  CellArrays cells;
  cells.corners = cornersOf(givenCorners);
  cells.levels = levelsOf(givenLevels);
  for (const auto& [key, values] : fields) cells.channels.push_back(channelOf(key, values, n));
  cells.origin = vec3Of(origin, "origin");
  cells.finestWidth = vec3Of(finestWidth, "finest_width");
  cells.periodic = periodic;
  cells.time = settingValue(settings::kTime, time);
  cells.timeUnit = std::move(timeUnit);
  cells.lengthUnit = std::move(lengthUnit);
  if (lengthUnitCm && !(std::isfinite(*lengthUnitCm) && *lengthUnitCm > 0))
    throw py::value_error(
        fmt::format("length_unit_cm must be a positive number of centimetres, "
                    "not {}",
                    *lengthUnitCm));
  cells.lengthUnitCentimetres = lengthUnitCm;
  for (const auto& [name, unit] : units.value_or(std::map<std::string, std::string>{}))
    if (!unit.empty()) cells.units[name] = unit;
  cells.source = std::move(source);
  cells.format = std::move(format);
  if (dimensions != 2 && dimensions != 3)
    throw py::value_error(fmt::format("dimensions must be 2 or 3, not {}", dimensions));
  cells.dimensions = dimensions;
  py::gil_scoped_release unlocked;
  return std::make_shared<Dataset>(fromCells(std::move(cells)));
}

// load's sizes of a builtin dataset, read as the command line reads --levels, --root-blocks,
// --target-cells and --gen-seed; nest takes more levels, as `amrstream gen` does.
BuiltinOptions builtinOptions(const std::string& path, const Given<std::optional<int>>& levels,
                              const Given<std::optional<int>>& rootBlocks,
                              const Given<std::optional<std::size_t>>& targetCells,
                              const Given<std::optional<std::uint64_t>>& genSeed) {
  Setting levelRange = settings::kLevels;
  if (path == "builtin:nest") levelRange.most = kMaxNestLevels;
  BuiltinOptions builtin;
  builtin.levels = settingValue(levelRange, levels).value_or(builtin.levels);
  builtin.rootBlocks = settingValue(settings::kRootBlocks, rootBlocks).value_or(builtin.rootBlocks);
  builtin.targetCells =
      settingValue(settings::kTargetCells, targetCells).value_or(builtin.targetCells);
  builtin.seed = settingValue(settings::kGenSeed, genSeed).value_or(builtin.seed);
  return builtin;
}

// Refuses a builtin dataset this machine cannot hold before generating it.
void checkBuiltinCells(const std::string& path, const BuiltinOptions& builtin) {
  if (path == "builtin:nest") {
    NestOptions nest;
    nest.levels = builtin.levels;
    checkGeneratedCells(nestCellCount(nest), "levels");
  } else if (path.starts_with("builtin:")) {
    checkBuiltinSize(builtin);
  }
}

std::shared_ptr<Dataset> loadDataset(const std::string& path, Given<std::optional<int>> levels,
                                     Given<std::optional<int>> rootBlocks,
                                     Given<std::optional<std::size_t>> targetCells,
                                     Given<std::optional<std::uint64_t>> genSeed,
                                     std::optional<std::string> lengthUnit,
                                     std::optional<std::map<std::string, std::string>> units) {
  const BuiltinOptions builtin = builtinOptions(path, levels, rootBlocks, targetCells, genSeed);
  checkBuiltinCells(path, builtin);
  const DeclaredUnits declared = declaredUnits(lengthUnit, units);
  py::gil_scoped_release unlocked;
  return std::make_shared<Dataset>(load(path, builtin, declared));
}

void bindDatasetClass(py::module_& m) {
  py::class_<Dataset, std::shared_ptr<Dataset>>(
      m, "Dataset", "Leaf cells of an AMR output, their fields, and what the file says of itself.")
      .def_property_readonly("source", &Dataset::source, "the path or description it came from")
      .def_property_readonly(
          "format", [](const Dataset& d) { return d.info().format; },
          "the file's format: 'FLASH', 'Enzo', 'AMReX', 'Gerris', 'ExaBricks', 'builtin', ...")
      .def_property_readonly("cell_count", &Dataset::cellCount, "the number of leaf cells")
      .def_property_readonly("field_names", &Dataset::channelNames,
                             "the fields' names, in the file's order")
      .def_property_readonly(
          "time", [](const Dataset& d) { return d.info().time; },
          "the snapshot's simulation time in time_unit, or None where the file states none")
      .def_property_readonly(
          "time_unit", [](const Dataset& d) { return d.info().timeUnit; },
          "the unit of time, e.g. 's' or 'code units (1 = 1.381e+16 s)'; '' where unknown")
      .def_property_readonly(
          "length_unit", [](const Dataset& d) { return d.info().lengthUnit; },
          "the unit of the coordinates, e.g. 'cm'; '' where unknown")
      .def_property_readonly(
          "length_unit_cm", [](const Dataset& d) { return d.info().lengthUnitCentimetres; },
          "the centimetres in one length_unit, where the file states it; else None")
      .def_property_readonly(
          "units",
          [](const Dataset& d) {
            return std::map<std::string, std::string>(d.info().units.begin(), d.info().units.end());
          },
          "{name: unit} for the channels whose unit the file states or load declared")
      .def_property_readonly(
          "periodic", [](const Dataset& d) { return periodicOf(d.info()); },
          "(x, y, z) periodicity the file declares, or None")
      .def_property_readonly(
          "origin", [](const Dataset& d) { return tuple3(d.transform().origin); },
          "physical position of corner (0, 0, 0)")
      .def_property_readonly(
          "dimensions", [](const Dataset& d) { return d.info().dimensions; },
          "2 for planar data, held as a slab across z = 0 whose vector is two channels; else 3")
      .def_property_readonly(
          "finest_width", [](const Dataset& d) { return tuple3(d.transform().spacing); },
          "(dx, dy, dz): the physical widths of a finest cell")
      .def_property_readonly(
          "domain_left_edge", [](const Dataset& d) { return tuple3(d.lower()); },
          "the physical lower corner of the cells' bounding box")
      .def_property_readonly(
          "domain_right_edge", [](const Dataset& d) { return tuple3(d.upper()); },
          "the physical upper corner of the cells' bounding box")
      .def_property_readonly(
          "corners",
          [](py::object self) {
            const Dataset& d = self.cast<const Dataset&>();
            return view3(d.corners().data(), d.cellCount(), self);
          },
          "(N, 3) int32: each cell's lower corner in finest cells, counted from `origin`")
      .def_property_readonly("levels", &fileLevels,
                             "(N,) int32: each cell's level as the file numbers them (level_name)")
      .def_property_readonly(
          "level_name", [](const Dataset& d) { return d.info().levelName; },
          "how `levels` are numbered, e.g. 'Enzo level (0 = root grid)'")
      .def(
          "field",
          [](py::object self, Given<std::string> name) {
            const Dataset& d = self.cast<const Dataset&>();
            const std::span<const float> values = d.channel(text("name", name.value));
            return view(values.data(), values.size(), self);
          },
          py::arg("name"), "(N,) float32 values of one field, in cell order (no copy)")
      .def("__repr__", [](const Dataset& d) {
        return fmt::format("<amrstream.Dataset {}: {} cells, fields {}>", d.source(), d.cellCount(),
                           fmt::join(d.channelNames(), ", "));
      });
}

void bindFieldClass(py::module_& m) {
  py::class_<Field, std::shared_ptr<Field>>(
      m, "Field", "A dataset made ready for tracing: vector, point data, bricks and regions.")
      .def_property_readonly("source", &Field::source, "the dataset's source")
      .def_property_readonly(
          "length_unit", [](const Field& f) { return f.info().lengthUnit; },
          "the unit of the coordinates, as the dataset states it (e.g. 'cm'); '' where it is "
          "unknown")
      .def_property_readonly(
          "length_unit_cm", [](const Field& f) { return f.info().lengthUnitCentimetres; },
          "the centimetres in one length_unit, where the dataset states it; else None")
      .def_property_readonly("vector_name", &Field::vectorName,
                             "the vector's name, e.g. 'vel' or '-grad(temp)'")
      .def_property_readonly("vector", &Field::vectorChannels,
                             "the names of the fields the vector is made of")
      .def_property_readonly(
          "frame_velocity", [](const Field& f) { return tuple3(f.frameVelocity()); },
          "(VX, VY, VZ) subtracted from the vector: the frame_velocity given or found by "
          "'auto'; zeros for none")
      .def_property_readonly("point_data", &Field::pointDataNames,
                             "the fields sampled at every point of a trace")
      .def_property_readonly(
          "periodic",
          [](const Field& f) {
            const flow::PeriodicAxes& p = volumeOf(f).periodic;
            return py::make_tuple(p[0], p[1], p[2]);
          },
          "(x, y, z): the axes traced as periodic")
      .def_property_readonly("brick_count", &Field::brickCount,
                             "the same-level bricks the cells are grouped into")
      .def_property_readonly("region_count", &Field::regionCount,
                             "the active brick regions space is cut into")
      .def_property_readonly(
          "domain_left_edge", [](const Field& f) { return tuple3(f.lower()); },
          "the physical lower corner of the domain")
      .def_property_readonly(
          "domain_right_edge", [](const Field& f) { return tuple3(f.upper()); },
          "the physical upper corner of the domain")
      .def("resample", &resampled, py::arg("dims") = 128, py::kw_only(),
           py::arg("box") = py::none(),
           "The reconstructed vector and point data on a uniform grid, as `amrstream resample` "
           "makes it: points at the centres of dims (N for the box's longest axis, or (NX, NY, "
           "NZ)) equal cells of `box` (x0, y0, z0, x1, y1, z1; default the domain). Returns a "
           "dict: 'origin' (the first point), 'spacing', 'dims', the vector (NX, NY, NZ, 3) and "
           "each channel (NX, NY, NZ) as float32 indexed [i, j, k], and 'valid' (NX, NY, NZ) "
           "bool, False (and zeros) where no region covers a point.")
      .def("__repr__", [](const Field& f) {
        return fmt::format("<amrstream.Field {} of {}: point data [{}], {} bricks, {} regions>",
                           f.vectorName(), f.source(), fmt::join(f.pointDataNames(), ", "),
                           f.brickCount(), f.regionCount());
      });
}

}  // namespace

void bindDataset(py::module_& m) {
  bindDatasetClass(m);
  bindFieldClass(m);
  m.def("load", &loadDataset, py::arg("path"), py::kw_only(), py::arg("levels") = py::none(),
        py::arg("root_blocks") = py::none(), py::arg("target_cells") = py::none(),
        py::arg("gen_seed") = py::none(), py::arg("length_unit") = py::none(),
        py::arg("units") = py::none(),
        "Loads a FLASH, Enzo, AMReX, Gerris or ExaBricks file, or builtin:NAME (rotation, abc, "
        "cloud, swirl; sized by levels, root_blocks, target_cells; or nest, sized by levels "
        "alone). length_unit and units ({name: unit}) declare the units of the coordinates and "
        "of channels (or the default vector, by its name) where the file states none; figures "
        "show them.");

  m.def("from_arrays", &fromArrays, py::arg("corners"), py::arg("levels"), py::arg("fields"),
        py::kw_only(), py::arg("origin") = py::make_tuple(0.0, 0.0, 0.0),
        py::arg("finest_width") = py::make_tuple(1.0, 1.0, 1.0), py::arg("periodic") = py::none(),
        py::arg("time") = py::none(), py::arg("time_unit") = "", py::arg("length_unit") = "",
        py::arg("length_unit_cm") = py::none(), py::arg("source") = "arrays",
        py::arg("format") = "arrays", py::arg("units") = py::none(), py::arg("dimensions") = 3,
        "A dataset from leaf cells: corners (N, 3) in finest cells from `origin`, levels (N,) "
        "with 0 the coarsest, fields {name: (N,) values}, units {name: unit} of the fields; "
        "length_unit_cm: the centimetres in a unit of length_unit, where it is code units; "
        "dimensions 2: planar data held as a slab across z = 0, whose vector is (a, b, 0).");

  m.def(
      "prepare",
      [](std::shared_ptr<Dataset> dataset, std::optional<std::string> vector,
         py::object frameVelocity, std::string pointData, std::string periodic,
         std::string interpolant) {
        FieldOptions options{vector.value_or(""), pointData, periodic, interpolant,
                             frameVelocityText(frameVelocity)};
        py::gil_scoped_release unlocked;
        return std::make_shared<Field>(buildField(*dataset, options));
      },
      py::arg("dataset").none(false), py::kw_only(), arg(settings::kVector) = py::none(),
      arg(settings::kFrameVelocity) = py::none(),
      arg(settings::kPointData) = FieldOptions{}.pointData,
      arg(settings::kPeriodic) = FieldOptions{}.periodic,
      arg(settings::kInterpolant) = FieldOptions{}.interpolant,
      ("Chooses the vector and the point data, adds periodic images, builds bricks and "
       "regions. frame_velocity is (VX, VY, VZ) or 'auto', here the vector's mean over the "
       "whole domain.\n\n" +
       settingsDoc(keywords::kField))
          .c_str());
}

}  // namespace amrstream::python
