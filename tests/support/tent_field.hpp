#pragma once
// The tent-basis reconstruction of three channels over ALL leaf cells of an AmrField, in double
// and independent of amrstream's bricks, regions and sampler (an oracle for tests):
//     v(p) = sum_i H_i(p) v_i / sum_i H_i(p),  H_i(p) = prod_d max(0, 1 - |c_i,d - p_d| / w_i),
// with c_i the cell's centre, w_i its width and p in finest-cell units. Of each level, only the
// 2x2x2 cells around p can weigh anything; one hash map per level from integer cell coordinates
// to the cell finds them.

#include <array>
#include <cstddef>
#include <glm/glm.hpp>
#include <string>
#include <unordered_map>
#include <vector>

#include "bricks/amr_field.hpp"

namespace amrstream::testing {

struct TentSample {
  enum class Status { Valid, OutOfDomain, Invalid };
  Status status = Status::OutOfDomain;
  glm::dvec3 value{0.0};
};

class TentField {
 public:
  // Throws InputError when a channel is absent.
  TentField(const bricks::AmrField& field, const std::array<std::string, 3>& channels);

  // OutOfDomain outside the cells' bounding box [lower, upper), Invalid where the weights sum to
  // at most 1e-20 (in a hole between cells).
  TentSample sample(glm::dvec3 p) const;
  // The level of the leaf cell containing p, or -1 where p is in no cell.
  int levelAt(glm::dvec3 p) const;

 private:
  struct CellKeyHash {
    std::size_t operator()(const glm::i64vec3& k) const;
  };
  using CellsByCoordinates = std::unordered_map<glm::i64vec3, std::size_t, CellKeyHash>;

  std::vector<CellsByCoordinates> levels_;  // indexed by level; empty for levels without cells
  std::vector<glm::dvec3> values_;
  glm::dvec3 lower_{0.0}, upper_{0.0};
};

}  // namespace amrstream::testing
