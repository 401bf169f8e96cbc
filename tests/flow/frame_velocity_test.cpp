// A vector relative to a moving frame (--frame-velocity). Oracles: the given velocity is taken
// off every value; auto's volume-weighted mean of a linear field over a box whose faces lie on
// the coarsest cells' faces is the field at the box's centre (each cell's centre value is its
// own mean, and the cells tile the box), over a plane's cells the field at the plane's centre;
// over the cells that hold points it is the mean over those cells each counted once, found here
// from the cells themselves; and it is the same bits on one thread as on many.

#include "flow/frame_velocity.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include "flow/vector_volume.hpp"
#include "input_error_of.hpp"
#include "random_amr.hpp"

namespace amrstream::flow {
namespace {

using ::testing::HasSubstr;

const VectorChannels kVector{{"vx", "vy", "vz"}, "v"};

// v = a + B c at the cell centres c (finest-cell units), on four levels over [0, 24)^3: the
// coarsest cells are 8 wide.
glm::dvec3 linearField(glm::dvec3 c) {
  return glm::dvec3(1.0 + 0.5 * c.x - 0.25 * c.z, -2.0 + 0.125 * c.y + 0.5 * c.x,
                    0.75 - 0.375 * c.z + 0.0625 * c.y);
}

bricks::AmrField linearAmr(std::uint64_t seed) {
  return testing::randomAmr(seed, {}, [](glm::dvec3 c) { return glm::vec3(linearField(c)); });
}

void expectNear(glm::dvec3 got, glm::dvec3 expected, double tolerance) {
  for (int axis = 0; axis < 3; ++axis) EXPECT_NEAR(got[axis], expected[axis], tolerance) << axis;
}

TEST(FrameVelocity, TheGivenVelocityIsTakenOffEveryValue) {
  const bricks::AmrField field = testing::randomAmr(7);
  const VectorVolume lab = buildVectorVolume(field, kVector);
  VectorChannels moving = kVector;
  moving.frameVelocity = glm::dvec3(0.5, -1.25, 3.0);
  const VectorVolume relative = buildVectorVolume(field, moving);
  EXPECT_EQ(lab.frameVelocity, glm::dvec3(0.0));
  EXPECT_EQ(relative.frameVelocity, moving.frameVelocity);
  ASSERT_EQ(relative.values.size(), lab.values.size());
  for (std::size_t slot = 0; slot < lab.values.size(); ++slot)
    ASSERT_EQ(relative.values[slot], glm::vec3(glm::dvec3(lab.values[slot]) - moving.frameVelocity))
        << slot;
}

TEST(FrameVelocity, AutoOverABoxOnTheCoarsestFacesIsTheFieldAtItsCentre) {
  for (const std::uint64_t seed : {1u, 2u}) {
    SCOPED_TRACE(seed);
    const bricks::AmrField field = linearAmr(seed);
    const VectorVolume lab = buildVectorVolume(field, kVector);
    const FrameRegion::Box box{glm::dvec3(8.0, 0.0, 8.0), glm::dvec3(24.0, 16.0, 16.0)};
    const glm::dvec3 centre(16.0, 8.0, 12.0);
    expectNear(meanVector(lab, {box, {}}), linearField(centre), 1e-5);
    // The whole domain: the field at (12, 12, 12).
    expectNear(meanVector(lab, {FrameRegion::Box{glm::dvec3(0.0), glm::dvec3(24.0)}, {}}),
               linearField(glm::dvec3(12.0)), 1e-5);

    // Built with the region, the volume's values are relative to that mean.
    VolumeOptions options;
    options.autoFrame = FrameRegion{box, {}};
    const VectorVolume relative = buildVectorVolume(field, kVector, options);
    EXPECT_EQ(relative.frameVelocity, meanVector(lab, {box, {}}));
    for (std::size_t slot = 0; slot < lab.values.size(); ++slot)
      ASSERT_EQ(relative.values[slot],
                glm::vec3(glm::dvec3(lab.values[slot]) - relative.frameVelocity));
  }
}

// A box of no thickness in z (a plane of seeds): the cells that hold z = 8, weighted by their
// area. The field there varies in x and y alone, whose mean over the plane is its value at the
// plane's centre.
TEST(FrameVelocity, AutoOverAPlaneWeighsItsCellsByTheirArea) {
  const bricks::AmrField field = testing::randomAmr(
      3, {}, [](glm::dvec3 c) { return glm::vec3(float(1.0 + 0.5 * c.x), float(-c.y), 2.0f); });
  const VectorVolume volume = buildVectorVolume(field, kVector);
  const FrameRegion::Box plane{glm::dvec3(0.0, 8.0, 8.0), glm::dvec3(24.0, 24.0, 8.0)};
  expectNear(meanVector(volume, {plane, {}}), glm::dvec3(7.0, -16.0, 2.0), 1e-5);
}

// The cells that hold the points, each once, weighted by its volume; found here by searching the
// cells themselves.
TEST(FrameVelocity, AutoOverPointsCountsEachCellThatHoldsOneOnce) {
  const bricks::AmrField field = testing::randomAmr(5);
  const VectorVolume volume = buildVectorVolume(field, kVector);
  const std::vector<glm::dvec3> points{{3.2, 17.5, 9.9}, {3.3, 17.6, 9.8}, {20.5, 1.5, 22.25}};
  std::vector<std::size_t> holding;
  for (const glm::dvec3& p : points)
    for (std::size_t i = 0; i < field.cellCount(); ++i) {
      const glm::dvec3 lower(field.lowers()[i]);
      const double width = double(1 << field.levels()[i]);
      if (glm::all(glm::greaterThanEqual(p, lower)) && glm::all(glm::lessThan(p, lower + width)))
        holding.push_back(i);
    }
  ASSERT_EQ(holding.size(), 3u);
  std::sort(holding.begin(), holding.end());
  holding.erase(std::unique(holding.begin(), holding.end()), holding.end());
  ASSERT_EQ(holding.size(), 2u);  // the first two points share a cell
  glm::dvec3 sum(0.0);
  double weight = 0.0;
  for (const std::size_t i : holding) {
    const double width = double(1 << field.levels()[i]);
    const double w = width * width * width;
    for (int axis = 0; axis < 3; ++axis) sum[axis] += w * double(field.channels()[axis].values[i]);
    weight += w;
  }
  expectNear(meanVector(volume, {std::nullopt, points}), sum / weight, 1e-6);
}

TEST(FrameVelocity, AutoOverNoCellIsRefusedNamingTheSetting) {
  const VectorVolume volume = buildVectorVolume(testing::randomAmr(5), kVector);
  EXPECT_THAT(testing::inputErrorOf([&] {
                meanVector(volume, {std::nullopt, {{-5.0, 1.0, 1.0}}});
              }),
              HasSubstr("--frame-velocity: auto takes the mean of the vector over the seeding "
                        "region, which holds no cell here"));
}

// Every MPI rank finds auto's velocity on its own: the sum must not depend on the threads.
TEST(FrameVelocity, AutoIsTheSameBitsOnOneThreadAsOnMany) {
  testing::RandomAmrOptions options;
  options.rootCells = glm::ivec3(6);
  const VectorVolume volume = buildVectorVolume(testing::randomAmr(9, options), kVector);
  const FrameRegion box{FrameRegion::Box{glm::dvec3(1.3, 2.7, 0.0), glm::dvec3(40.1, 47.0, 33.3)},
                        {}};
  const glm::dvec3 many = meanVector(volume, box);
  tbb::task_arena one(1);
  const glm::dvec3 single = one.execute([&] { return meanVector(volume, box); });
  EXPECT_EQ(many, single);
}

}  // namespace
}  // namespace amrstream::flow
