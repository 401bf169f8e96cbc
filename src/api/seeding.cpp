#include "amrstream/seeding.hpp"

#include <fmt/format.h>

#include <utility>

#include "amrstream/error.hpp"
#include "api/handles.hpp"
#include "api/seed_choice.hpp"
#include "flow/seed_strategies.hpp"
#include "flow/trace_accumulator.hpp"
#include "flow/trace_set.hpp"
#include "util/host_memory.hpp"

namespace amrstream {

namespace {

glm::dvec3 corner(const std::vector<double>& v, int which) {
  return glm::dvec3(v[3 * which], v[3 * which + 1], v[3 * which + 2]);
}

void checkSize(const std::vector<double>& values, const char* option) {
  if (values.size() != 6)
    throw settingError(option,
                       fmt::format("needs 6 numbers x0,y0,z0,x1,y1,z1, not {}", values.size()));
}

// The seed box: the request's box, checked against the domain, or the domain itself.
std::pair<glm::dvec3, glm::dvec3> seedBox(const SeedRequest& request, const Domain& domain) {
  const glm::dvec3 domainLo = domain.lower, domainHi = domain.upper;
  if (request.box.empty()) return {domainLo, domainHi};
  checkSize(request.box, "seed_box");
  const glm::dvec3 lo = corner(request.box, 0), hi = corner(request.box, 1);
  if (glm::any(glm::greaterThan(lo, hi)))
    throw settingError("seed_box", "the lower corner must not exceed the upper corner");
  if (glm::any(glm::lessThan(lo, domainLo)) || glm::any(glm::greaterThan(hi, domainHi)))
    throw settingError(
        "seed_box",
        fmt::format("the box reaches outside the domain [{:g}, {:g}) x [{:g}, "
                    "{:g}) x [{:g}, {:g})",
                    domainLo.x, domainHi.x, domainLo.y, domainHi.y, domainLo.z, domainHi.z));
  return {lo, hi};
}

// The least host memory a seed takes through a run: its point and the text naming its origin in
// the seed list, and one traced line of one point (trace_memory.hpp counts its lines).
const double kLeastBytesPerSeed =
    double(sizeof(glm::dvec3) + sizeof(std::string) + 32 + flow::kHeldBytesPerLine +
           flow::TraceSet::bytesPerPoint(0, false));

}  // namespace

void checkSeedCount(double count, const std::string& option) {
  if (count > double(kMaxSeedCount))
    throw settingError(option, fmt::format("{:.0f} seeds are more than the {} one run may trace "
                                           "(lines are numbered in 32 bits, two per seed)",
                                           count, kMaxSeedCount));
  const double bytes = count * kLeastBytesPerSeed;
  const double limit = kTraceMemoryShare * physicalMemoryBytes();
  if (limit > 0.0 && bytes > limit)
    throw settingError(option,
                       fmt::format("{:.0f} seeds need at least {:.1f} GiB ({:.0f} bytes each "
                                   "for the seed and its traced line), more than the {:.1f} "
                                   "GiB (3/4 of the memory) traces may take on this machine",
                                   count, bytes / 0x1p30, kLeastBytesPerSeed, limit / 0x1p30));
}

Domain domainOf(const bricks::AmrField& cells) {
  const WorldTransform& t = cells.transform();
  return {t.toPhysical(glm::dvec3(cells.bounds().lower)),
          t.toPhysical(glm::dvec3(cells.bounds().upper)), t.spacing, nullptr,
          cells.info().dimensions == 2};
}

Domain domainOf(const flow::VectorVolume& volume) {
  return {flow::domainLower(volume), flow::domainUpper(volume), volume.transform.spacing, &volume,
          volume.planar};
}

void checkSeedRequest(const SeedRequest& request) {
  if (!request.points.empty() || !request.file.empty()) return;
  if (request.line.empty() && request.density.empty() && request.grid.size() == 3)
    checkSeedCount(double(request.grid[0]) * double(request.grid[1]) * double(request.grid[2]),
                   "seed_grid");
  else
    checkSeedCount(double(request.count), "count");
}

namespace {

// 2D data: every seed on the data's plane, the middle of its slab [lower, upper], where lines
// stay.
void ontoPlane(const glm::dvec3& lower, const glm::dvec3& upper, flow::SeedList& seeds) {
  const double plane = 0.5 * (lower.z + upper.z);
  for (glm::dvec3& p : seeds.points) p.z = plane;
}

flow::SeedList seedsAsAsked(const SeedRequest& request, const Domain& domain,
                            const bricks::AmrField* cells, std::string& description,
                            const flow::SharedCells* shared) {
  if (!request.points.empty()) {
    description = "given points";
    flow::SeedList seeds;
    seeds.points = request.points;
    seeds.origin = [](std::size_t i) { return fmt::format("seeds[{}]", i); };
    return seeds;
  }
  if (!request.file.empty()) {
    description = request.file;
    return flow::readSeedFile(request.file);
  }
  if (!request.line.empty()) {
    checkSize(request.line, "seed_line");
    description = "a rake (--seed-line)";
    return flow::seedsAlongLine(corner(request.line, 0), corner(request.line, 1), request.count);
  }
  if (!request.density.empty()) {
    if (!cells) throw settingError("seed_density", "needs the dataset's cells");
    description = fmt::format("random cells with {} at or above its {:g}th percentile{} (seed {})",
                              request.density, request.percentile,
                              request.weighted ? ", weighted by it" : "", request.seed);
    return flow::seedsInDensestCells(*cells, {request.density, request.percentile, request.weighted,
                                              request.count, request.seed, shared});
  }
  auto [lo, hi] = seedBox(request, domain);
  // Keep seeds off the domain's open upper faces, where rounding to float could put them.
  hi = glm::min(hi, domain.upper - 1e-4 * domain.finestWidth);
  if (!request.grid.empty()) {
    if (request.grid.size() != 3) throw settingError("seed_grid", "needs 3 counts NX,NY,NZ");
    glm::ivec3 counts(request.grid[0], request.grid[1], request.grid[2]);
    if (glm::any(glm::lessThan(counts, glm::ivec3(1))))
      throw settingError("seed_grid", "every count must be at least 1");
    description = fmt::format("a {}x{}x{} grid in a box", counts.x, counts.y, counts.z);
    if (domain.planar && counts.z > 1) {
      // Its layers would all land on the data's plane, each seed NZ times.
      counts.z = 1;
      description += " (one layer: the data are 2D)";
    }
    return flow::seedsOnGrid(lo, hi, counts);
  }
  description = fmt::format("random (seed {}) in {}", request.seed,
                            domain.volume ? "the cells of a box" : "a box");
  if (domain.volume)
    return flow::randomSeedsInCells(*domain.volume, lo, hi, request.count, request.seed);
  return flow::randomSeedsInBox(lo, hi, request.count, request.seed);
}

}  // namespace

flow::SeedList chooseSeeds(const SeedRequest& request, const Domain& domain,
                           const bricks::AmrField* cells, std::string& description,
                           const flow::SharedCells* shared) {
  checkSeedRequest(request);
  flow::SeedList seeds = seedsAsAsked(request, domain, cells, description, shared);
  if (domain.planar) {
    ontoPlane(domain.lower, domain.upper, seeds);
    description += ", on the 2D data's plane";
  }
  return seeds;
}

void placeSeeds(const flow::VectorVolume& volume, flow::SeedList& seeds) {
  if (volume.planar) ontoPlane(flow::domainLower(volume), flow::domainUpper(volume), seeds);
  flow::closeUpperFaces(volume, seeds);
  flow::checkSeedsInDomain(volume, seeds);
}

std::vector<glm::dvec3> makeSeeds(const SeedRequest& request, const Field& field,
                                  std::string* description) {
  std::string text;
  const std::optional<Dataset>& dataset = field.dataset();
  flow::SeedList seeds =
      chooseSeeds(request, domainOf(volumeOf(field)), dataset ? &cellsOf(*dataset) : nullptr, text);
  if (description) *description = text;
  return std::move(seeds.points);
}

std::vector<glm::dvec3> makeSeeds(const SeedRequest& request, const Dataset& dataset,
                                  std::string* description) {
  std::string text;
  const bricks::AmrField& cells = cellsOf(dataset);
  flow::SeedList seeds = chooseSeeds(request, domainOf(cells), &cells, text);
  if (description) *description = text;
  return std::move(seeds.points);
}

}  // namespace amrstream
