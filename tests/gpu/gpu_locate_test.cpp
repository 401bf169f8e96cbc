// Every GPU backend's point location (locateRegion: the domain check, then the region tree, the
// ray query or the ray tracing pipeline) against brute force: the one region whose half-open box
// holds the point, or -1 outside the domain (the cells' bounding box) and in empty space.

#include <gtest/gtest.h>

#include <random>

#include "gpu/gpu_tracer.hpp"
#include "gpu_test.hpp"
#include "random_amr.hpp"

namespace amrstream::gpu {
namespace {

std::int32_t bruteForceLocate(const flow::VectorVolume& volume, glm::vec3 p) {
  if (glm::any(glm::lessThan(p, glm::vec3(volume.domain.lower))) ||
      glm::any(glm::greaterThanEqual(p, glm::vec3(volume.domain.upper))))
    return -1;
  std::int32_t found = -1;
  for (std::size_t r = 0; r < volume.regions.regions.size(); ++r) {
    const shared::Region& region = volume.regions.regions[r];
    const glm::dvec3 lower = 0.5 * glm::dvec3(region.lower), upper = 0.5 * glm::dvec3(region.upper);
    if (glm::all(glm::greaterThanEqual(glm::dvec3(p), lower)) &&
        glm::all(glm::lessThan(glm::dvec3(p), upper))) {
      EXPECT_EQ(found, -1) << "regions overlap at " << p.x << "," << p.y << "," << p.z;
      found = std::int32_t(r);
    }
  }
  return found;
}

// Region corners, face centres and edge midpoints (on shared faces, edges and corners), the
// domain's lower and upper faces and corners, and random points in and around the domain.
std::vector<glm::vec3> probePoints(const flow::VectorVolume& volume) {
  std::vector<glm::vec3> points;
  for (const shared::Region& r : volume.regions.regions) {
    const glm::vec3 lo = 0.5f * glm::vec3(r.lower), hi = 0.5f * glm::vec3(r.upper),
                    mid = 0.5f * (lo + hi);
    for (int corner = 0; corner < 8; ++corner)
      points.push_back(
          glm::mix(lo, hi, glm::vec3(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1)));
    for (int axis = 0; axis < 3; ++axis) {
      glm::vec3 face = mid, edge = lo;
      face[axis] = lo[axis];
      points.push_back(face);
      face[axis] = hi[axis];
      points.push_back(face);
      edge[axis] = mid[axis];
      points.push_back(edge);
    }
  }
  const glm::vec3 dlo(volume.domain.lower), dhi(volume.domain.upper);
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec3 p =
        glm::mix(dlo, dhi, glm::vec3(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1));
    points.push_back(p);
  }
  for (int axis = 0; axis < 3; ++axis) {
    glm::vec3 p = 0.5f * (dlo + dhi);
    p[axis] = dlo[axis];
    points.push_back(p);  // on the lower face: inside
    p[axis] = dhi[axis];
    points.push_back(p);  // on the upper face: outside
  }
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<float> u(-0.1f, 1.1f);
  for (int i = 0; i < 4000; ++i)
    points.push_back(dlo + glm::vec3(u(rng), u(rng), u(rng)) * (dhi - dlo));
  return points;
}

class GpuLocateTest : public testing::GpuTest, public ::testing::WithParamInterface<Backend> {
 protected:
  vk::CapabilitySet required() const override { return requiredCapabilities(GetParam()); }
};

TEST_P(GpuLocateTest, MatchesBruteForceOnFacesEdgesCornersAndOutside) {
  for (std::uint64_t seed : {4u, 12u}) {
    testing::RandomAmrOptions layout;
    layout.levels = 4;
    layout.rootCells = glm::ivec3(3, 2, 2);
    layout.origin = glm::ivec3(-8, 16, 0);
    const bricks::AmrField field = testing::randomAmr(seed, layout);
    const flow::VectorVolume volume = flow::buildVectorVolume(field, {{"vx", "vy", "vz"}, "v"});
    const std::vector<glm::vec3> points = probePoints(volume);
    GpuTracer tracer(ctx(), GetParam(), volume);
    const std::vector<std::int32_t> located = tracer.locate(points);
    ASSERT_EQ(located.size(), points.size());
    std::size_t inside = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
      const std::int32_t expected = bruteForceLocate(volume, points[i]);
      inside += expected >= 0;
      ASSERT_EQ(located[i], expected) << "seed " << seed << " point " << i << " at " << points[i].x
                                      << "," << points[i].y << "," << points[i].z;
    }
    EXPECT_GT(inside, points.size() / 3);
    EXPECT_LT(inside, points.size());
  }
}

INSTANTIATE_TEST_SUITE_P(Backends, GpuLocateTest,
                         ::testing::Values(Backend::RayQuery, Backend::Pipeline, Backend::Compute),
                         [](const auto& info) { return std::string(backendName(info.param)); });

}  // namespace
}  // namespace amrstream::gpu
