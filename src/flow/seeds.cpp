#include "seeds.hpp"

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <random>
#include <string>
#include <string_view>

#include "amrstream/error.hpp"
#include "sampler.hpp"
#include "util/host_memory.hpp"
#include "util/input_file.hpp"

namespace amrstream::flow {

namespace {

// The whole file, which must be a regular file (checked before opening: a FIFO would block, a
// device never end) that fits in memory and keeps its size while it is read.
std::string wholeSeedFile(const std::filesystem::path& path) {
  const std::uint64_t size = regularFileSize(path);
  const double limit = kTraceMemoryShare * physicalMemoryBytes();
  if (limit > 0.0 && double(size) > limit)
    throw InputError(path.string(), fmt::format("the file's {:.1f} GiB are more than the {:.1f} "
                                                "GiB (3/4 of the memory) seeds may take here",
                                                double(size) / 0x1p30, limit / 0x1p30));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string(), "cannot open the seeds file");
  std::string text(static_cast<std::size_t>(size), '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  const auto read = static_cast<std::uint64_t>(in.gcount());
  if (in.bad()) throw InputError(path.string(), "cannot read the seeds file");
  const bool grew = read == size && in.peek() != std::ifstream::traits_type::eof();
  if (read != size || grew)
    throw InputError(path.string(), fmt::format("the file changed while it was read: {} bytes "
                                                "when opened, {} read",
                                                size, grew ? "more" : std::to_string(read)));
  return text;
}

}  // namespace

SeedList readSeedFile(const std::filesystem::path& path) {
  const std::string text = wholeSeedFile(path);
  SeedList seeds;
  std::vector<std::uint32_t> lines;  // each seed's line
  std::size_t number = 0;
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t end = std::min(text.find('\n', at), text.size());
    std::string line = text.substr(at, end - at);
    at = end + 1;
    ++number;
    if (auto hash = line.find('#'); hash != std::string::npos) line.resize(hash);
    for (char& c : line)
      if (c == ',' || c == '\t' || c == '\r') c = ' ';
    if (line.find_first_not_of(' ') == std::string::npos) continue;
    const auto where = [&] { return fmt::format("{}:{}", path.string(), number); };
    glm::dvec3 p;
    char* cursor = line.data();
    for (int axis = 0; axis < 3; ++axis) {
      char* end = nullptr;
      p[axis] = std::strtod(cursor, &end);
      if (end == cursor)
        throw InputError(where(), fmt::format("expected three numbers 'x y z', got '{}'", line));
      cursor = end;
    }
    if (std::string_view(cursor).find_first_not_of(' ') != std::string_view::npos)
      throw InputError(where(), fmt::format("unexpected text after 'x y z': '{}'", cursor));
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw InputError(where(), "the seed has a non-finite coordinate");
    seeds.points.push_back(p);
    lines.push_back(static_cast<std::uint32_t>(number));
  }
  if (seeds.points.empty()) throw InputError(path.string(), "the seeds file holds no seeds");
  seeds.origin = [file = path.string(), lines = std::move(lines)](std::size_t i) {
    return fmt::format("{}:{}", file, lines[i]);
  };
  return seeds;
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
  }
  seeds.origin = [](std::size_t i) { return fmt::format("random seed #{}", i); };
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

std::string SeedList::originOf(std::size_t i) const {
  return origin ? origin(i) : fmt::format("seed #{}", i);
}

void checkSeedsInDomain(const VectorVolume& volume, const SeedList& seeds) {
  const auto sampleAt = [&](std::size_t i) {
    return sampleVector(volume, toCellPoint(volume.transform.toCellUnits(seeds.points[i])));
  };
  // A point in a cell has a valid sample: its cell's tent is at least 1/8 there, and the values
  // are finite and bounded so that their weighted sums are (value_range.hpp).
  const auto valid = [&](std::size_t i) {
    return volume.surelyInACell(volume.transform.toCellUnits(seeds.points[i])) || sampleAt(i).valid;
  };
  // The first seed without a valid sample, found on all cores.
  const std::size_t n = seeds.points.size();
  std::atomic<std::size_t> first{n};
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 4096),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t i = range.begin(); i < range.end(); ++i) {
                        std::size_t known = first.load(std::memory_order_relaxed);
                        if (i >= known) return;
                        if (valid(i)) continue;
                        while (i < known && !first.compare_exchange_weak(known, i)) {
                        }
                        return;
                      }
                    });
  const std::size_t i = first.load();
  if (i == n) return;
  const glm::dvec3 p = seeds.points[i];
  if (sampleAt(i).located)
    throw InputError(seeds.originOf(i),
                     fmt::format("seed ({:g}, {:g}, {:g}) lies on the outer face of the data, "
                                 "next to empty space, where no cell's tent function reaches: "
                                 "move it into a cell",
                                 p.x, p.y, p.z));
  const glm::dvec3 lo = domainLower(volume), hi = domainUpper(volume);
  throw InputError(seeds.originOf(i),
                   fmt::format("seed ({:g}, {:g}, {:g}) is outside the domain [{:g}, {:g}) x "
                               "[{:g}, {:g}) x [{:g}, {:g})",
                               p.x, p.y, p.z, lo.x, hi.x, lo.y, hi.y, lo.z, hi.z));
}

}  // namespace amrstream::flow
