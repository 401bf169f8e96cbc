// Seeds as numpy arrays, made as the command line's seeding options make them.

#include <pybind11/stl.h>

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "amrstream/error.hpp"
#include "amrstream/field.hpp"
#include "amrstream/seeding.hpp"
#include "api/handles.hpp"
#include "api/seed_choice.hpp"
#include "bindings.hpp"
#include "numpy_views.hpp"
#include "setting_args.hpp"

namespace amrstream::python {

namespace {

// The domain of a Dataset or a Field.
Domain domainOfTarget(py::handle target) {
  if (py::isinstance<Dataset>(target)) return domainOf(cellsOf(target.cast<const Dataset&>()));
  if (py::isinstance<Field>(target)) return domainOf(volumeOf(target.cast<const Field&>()));
  throw py::type_error("expected an amrstream.Dataset or amrstream.Field");
}

py::array toNumpy(const flow::SeedList& seeds) {
  py::array_t<double> out({py::ssize_t(seeds.points.size()), py::ssize_t(3)});
  std::memcpy(out.mutable_data(), seeds.points.data(), seeds.points.size() * sizeof(glm::dvec3));
  return out;
}

// The seeding settings as the seeds_* functions name their keywords.
std::string seedKeyword(std::string_view setting) {
  if (setting == settings::kSeedBox.name) return "box";
  if (setting == settings::kSeedGrid.name) return "counts";
  if (setting == settings::kSeedPercentile.name) return "percentile";
  if (setting == settings::kSeedDensity.name) return "field";
  return std::string(setting);
}

// The library's seeds for the request, its errors naming the keywords of seeds_*.
flow::SeedList chosenSeeds(const SeedRequest& request, const Domain& domain,
                           const bricks::AmrField* cells) {
  std::string description;
  try {
    py::gil_scoped_release unlocked;
    return chooseSeeds(request, domain, cells, description);
  } catch (const InputError& e) {
    if (!e.isAboutSetting()) throw;
    throw settingError(seedKeyword(e.source()), spellSettings(e.problem(), seedKeyword));
  }
}

// box: 6 finite numbers a float holds, as --seed-box.
std::vector<double> boxOf(py::handle box) {
  if (box.is_none()) return {};
  const auto bounds = settingValue<std::array<double, 6>>(settings::kSeedBox, box, "box");
  return {bounds.begin(), bounds.end()};
}

py::array seedsFor(const SeedRequest& request, const Domain& domain,
                   const bricks::AmrField* cells) {
  return toNumpy(chosenSeeds(request, domain, cells));
}

// Random seeds in the target's cells, never in holes of its domain, as the command line draws
// them: a Dataset's cell layout is built for the draw, a Field has its own.
py::array randomSeedsFor(const SeedRequest& request, py::handle target) {
  if (!py::isinstance<Dataset>(target)) return seedsFor(request, domainOfTarget(target), nullptr);
  const Dataset& cells = target.cast<const Dataset&>();
  flow::VectorVolume layout;
  {
    py::gil_scoped_release unlocked;
    checkSeedRequest(request);
    layout = flow::buildCellLayout(cellsOf(cells));
  }
  return seedsFor(request, domainOf(layout), nullptr);
}

}  // namespace

void bindSeeding(py::module_& m) {
  namespace s = settings;
  const SeedRequest defaults;
  m.def(
      "seeds_random",
      [](py::handle target, Given<std::size_t> count, Given<std::optional<std::vector<double>>> box,
         Given<std::uint64_t> seed) {
        SeedRequest r;
        r.count = settingValue(s::kCount, count);
        r.box = boxOf(box.value);
        r.seed = settingValue(s::kSeed, seed);
        return randomSeedsFor(r, target);
      },
      py::arg("target"), arg(s::kCount) = defaults.count, py::kw_only(),
      py::arg("box") = py::none(), arg(s::kSeed) = defaults.seed,
      "(count, 3) random points in the cells within box (x0, y0, z0, x1, y1, z1; default: the "
      "domain), never in holes between the cells.");
  m.def(
      "seeds_grid",
      [](py::handle target, Given<std::array<int, 3>> counts,
         Given<std::optional<std::vector<double>>> box) {
        const auto grid = settingValue(s::kSeedGrid, counts, "counts");
        SeedRequest r;
        r.grid = {grid.begin(), grid.end()};
        r.box = boxOf(box.value);
        return seedsFor(r, domainOfTarget(target), nullptr);
      },
      py::arg("target"), py::arg("counts"), py::kw_only(), py::arg("box") = py::none(),
      "A regular (nx, ny, nz) grid of points in box (default: the domain); a count of 1 on an "
      "axis of a flat box makes a plane.");
  m.def(
      "seeds_line",
      [](Given<std::array<double, 3>> start, Given<std::array<double, 3>> end,
         Given<std::size_t> count) {
        const auto from = settingValue(s::kSeedLine, start, "start");
        const auto to = settingValue(s::kSeedLine, end, "end");
        SeedRequest r;
        r.line = {from[0], from[1], from[2], to[0], to[1], to[2]};
        r.count = settingValue(s::kCount, count);
        return seedsFor(r, {}, nullptr);
      },
      py::arg("start"), py::arg("end"), arg(s::kCount) = defaults.count,
      "count points evenly from start to end, both included (a rake).");
  m.def(
      "seeds_densest",
      [](std::shared_ptr<Dataset> dataset, const std::string& field, Given<std::size_t> count,
         Given<double> percentile, bool weighted, Given<std::uint64_t> seed) {
        SeedRequest r;
        r.density = field;
        r.count = settingValue(s::kCount, count);
        r.percentile = settingValue(s::kSeedPercentile, percentile, "percentile");
        r.weighted = weighted;
        r.seed = settingValue(s::kSeed, seed);
        return seedsFor(r, domainOf(cellsOf(*dataset)), &cellsOf(*dataset));
      },
      py::arg("dataset").none(false), py::arg("field"), arg(s::kCount) = defaults.count,
      py::kw_only(), py::arg("percentile") = defaults.percentile, py::arg("weighted") = false,
      arg(s::kSeed) = defaults.seed,
      "count random points in random cells whose field is at or above its percentile "
      "(weighted: cells picked in proportion to the field).");
}

}  // namespace amrstream::python
