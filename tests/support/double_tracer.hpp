#pragma once
// An independent double-precision streamline tracer for tests: classic RK4 in finest-cell units,
// a step as amrstream's `time` step mode defines it (docs/architecture.md, "Integration"),
//     k(p) = h v(p) / spacing,  x_{n+1} = x_n + (k1 + 2 k2 + 2 k3 + k4) / 6,
// with stages at x_n, x_n + k1/2, x_n + k2/2, x_n + k3 and v the tent reconstruction over all
// leaf cells (tent_field.hpp). A step whose stage points or end point cannot be sampled is not
// taken: the trace ends at its last point, as amrstream's does.

#include <array>
#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "bricks/amr_field.hpp"
#include "tent_field.hpp"

namespace amrstream::testing {

enum class DoubleTraceEnd { StepsDone, OutOfDomain, InvalidSample };

struct DoubleTrace {
  std::vector<glm::dvec3> positions;  // physical: the seed, then the end of every step taken
  DoubleTraceEnd end = DoubleTraceEnd::StepsDone;

  std::size_t steps() const { return positions.size() - 1; }
};

class DoubleTracer {
 public:
  // `vector` names the three channels traced. Throws InputError when one is absent.
  DoubleTracer(const bricks::AmrField& field, const std::array<std::string, 3>& vector);

  // `seed` in physical coordinates, `h` in physical time; at most `steps` steps.
  DoubleTrace trace(glm::dvec3 seed, double h, std::uint32_t steps) const;

  const TentField& field() const { return field_; }
  const WorldTransform& transform() const { return transform_; }

 private:
  TentField field_;
  WorldTransform transform_;
};

}  // namespace amrstream::testing
