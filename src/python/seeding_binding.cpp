// Seeds as numpy arrays, made as the command line's seeding options make them.

#include <pybind11/stl.h>

#include "amrstream/field.hpp"
#include "amrstream/seeding.hpp"
#include "api/handles.hpp"
#include "api/seed_choice.hpp"
#include "bindings.hpp"
#include "numpy_views.hpp"

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

std::vector<double> boxOf(const std::optional<std::vector<double>>& box) {
  if (!box) return {};
  if (box->size() != 6) throw py::value_error("box must be 6 numbers: x0, y0, z0, x1, y1, z1");
  return *box;
}

py::array seedsFor(const SeedRequest& request, const Domain& domain,
                   const bricks::AmrField* cells) {
  std::string description;
  flow::SeedList seeds;
  {
    py::gil_scoped_release unlocked;
    seeds = chooseSeeds(request, domain, cells, description);
  }
  return toNumpy(seeds);
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
  m.def(
      "seeds_random",
      [](py::handle target, std::size_t count, std::optional<std::vector<double>> box,
         std::uint64_t seed) {
        SeedRequest r;
        r.count = count;
        r.box = boxOf(box);
        r.seed = seed;
        return randomSeedsFor(r, target);
      },
      py::arg("target"), py::arg("count") = SeedRequest{}.count, py::kw_only(),
      py::arg("box") = py::none(), py::arg("seed") = SeedRequest{}.seed,
      "(count, 3) random points in the cells within box (x0, y0, z0, x1, y1, z1; default: the "
      "domain), never in holes between the cells.");
  m.def(
      "seeds_grid",
      [](py::handle target, std::array<int, 3> counts, std::optional<std::vector<double>> box) {
        SeedRequest r;
        r.grid = {counts[0], counts[1], counts[2]};
        r.box = boxOf(box);
        return seedsFor(r, domainOfTarget(target), nullptr);
      },
      py::arg("target"), py::arg("counts"), py::kw_only(), py::arg("box") = py::none(),
      "A regular (nx, ny, nz) grid of points in box (default: the domain); a count of 1 on an "
      "axis of a flat box makes a plane.");
  m.def(
      "seeds_line",
      [](std::array<double, 3> start, std::array<double, 3> end, std::size_t count) {
        SeedRequest r;
        r.line = {start[0], start[1], start[2], end[0], end[1], end[2]};
        r.count = count;
        return seedsFor(r, {}, nullptr);
      },
      py::arg("start"), py::arg("end"), py::arg("count") = SeedRequest{}.count,
      "count points evenly from start to end, both included (a rake).");
  m.def(
      "seeds_densest",
      [](std::shared_ptr<Dataset> dataset, const std::string& field, std::size_t count,
         double percentile, bool weighted, std::uint64_t seed) {
        SeedRequest r;
        r.density = field;
        r.count = count;
        r.percentile = percentile;
        r.weighted = weighted;
        r.seed = seed;
        return seedsFor(r, domainOf(cellsOf(*dataset)), &cellsOf(*dataset));
      },
      py::arg("dataset").none(false), py::arg("field"), py::arg("count") = SeedRequest{}.count,
      py::kw_only(), py::arg("percentile") = SeedRequest{}.percentile, py::arg("weighted") = false,
      py::arg("seed") = SeedRequest{}.seed,
      "count random points in random cells whose field is at or above its percentile "
      "(weighted: cells picked in proportion to the field).");
}

}  // namespace amrstream::python
