#include "seeds.hpp"

#include <algorithm>

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <random>

#include "sampler.hpp"
#include "util/input_error.hpp"

namespace amrstream::flow {

SeedList readSeedFile(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path.string(), "cannot open the seeds file");
  SeedList seeds;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (auto hash = line.find('#'); hash != std::string::npos) line.resize(hash);
    for (char& c : line)
      if (c == ',' || c == '\t' || c == '\r') c = ' ';
    if (line.find_first_not_of(' ') == std::string::npos) continue;
    const std::string where = fmt::format("{}:{}", path.string(), number);
    glm::dvec3 p;
    char* cursor = line.data();
    for (int axis = 0; axis < 3; ++axis) {
      char* end = nullptr;
      p[axis] = std::strtod(cursor, &end);
      if (end == cursor)
        throw InputError(where, fmt::format("expected three numbers 'x y z', got '{}'", line));
      cursor = end;
    }
    if (std::string_view(cursor).find_first_not_of(' ') != std::string_view::npos)
      throw InputError(where, fmt::format("unexpected text after 'x y z': '{}'", cursor));
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw InputError(where, "the seed has a non-finite coordinate");
    seeds.points.push_back(p);
    seeds.origins.push_back(where);
  }
  if (seeds.points.empty()) throw InputError(path.string(), "the seeds file holds no seeds");
  return seeds;
}

void writeSeedFile(const std::filesystem::path& path, const SeedList& seeds) {
  std::ofstream out(path);
  if (!out) throw InputError(path.string(), "cannot create the seeds file");
  out << "# amrstream seeds: x y z in physical coordinates\n";
  for (const glm::dvec3& p : seeds.points)
    out << fmt::format("{:.17g} {:.17g} {:.17g}\n", p.x, p.y, p.z);
  if (!out.flush()) throw InputError(path.string(), "write failed (disk full?)");
}

SeedList randomSeedsInBox(glm::dvec3 lower, glm::dvec3 upper, std::size_t count,
                          std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  // 53 random bits -> [0, 1); unlike std::uniform_real_distribution this is the same everywhere.
  const auto unit = [&] { return double(rng() >> 11) * 0x1.0p-53; };
  SeedList seeds;
  for (std::size_t i = 0; i < count; ++i) {
    const glm::dvec3 t(unit(), unit(), unit());
    seeds.points.push_back(lower + t * (upper - lower));
    seeds.origins.push_back(fmt::format("random seed #{}", i));
  }
  return seeds;
}

glm::dvec3 domainLower(const VectorVolume& volume) {
  return volume.transform.toPhysical(glm::dvec3(volume.domain.lower));
}
glm::dvec3 domainUpper(const VectorVolume& volume) {
  return volume.transform.toPhysical(glm::dvec3(volume.domain.upper));
}

void closeUpperFaces(const VectorVolume& volume, SeedList& seeds) {
  const glm::dvec3 upper = domainUpper(volume);
  const glm::dvec3 inside = upper - 1e-4 * volume.transform.spacing;
  for (glm::dvec3& p : seeds.points)
    for (int a = 0; a < 3; ++a)
      if (p[a] >= inside[a] && p[a] <= upper[a]) p[a] = std::min(p[a], inside[a]);
}

void checkSeedsInDomain(const VectorVolume& volume, const SeedList& seeds) {
  for (std::size_t i = 0; i < seeds.points.size(); ++i) {
    const glm::dvec3 p = seeds.points[i];
    if (locateRegion(volume, glm::vec3(volume.transform.toCellUnits(p))) >= 0) continue;
    const glm::dvec3 lo = domainLower(volume), hi = domainUpper(volume);
    throw InputError(seeds.origins[i],
                     fmt::format("seed ({:g}, {:g}, {:g}) is outside the domain [{:g}, {:g}) x "
                                 "[{:g}, {:g}) x [{:g}, {:g})",
                                 p.x, p.y, p.z, lo.x, hi.x, lo.y, hi.y, lo.z, hi.z));
  }
}

}  // namespace amrstream::flow
