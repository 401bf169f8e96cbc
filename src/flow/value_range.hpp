#pragma once
// The range of values the tracer's float32 arithmetic can take without overflowing: speeds are
// |v| = sqrt(vx² + vy² + vz²), and the tent sum adds up to a few dozen weighted values. A field
// beyond these bounds would write inf into Speed or the point data, so it is refused by name
// before tracing (rescale it: amrstream's steps do not depend on the vector's units in `arc` and
// `time` modes).

#include <span>
#include <string>

#include "bricks/amr_field.hpp"
#include "vector_selection.hpp"

namespace amrstream::flow {

inline constexpr float kMaxVectorComponent = 1e18f;  // |v|² stays below 3e36
inline constexpr float kMaxPointDataValue = 1e36f;   // a sum of 64 weighted values stays finite

// Throws InputError naming `source`, the channel, the cell and the bound when a value's
// magnitude passes `bound`.
void checkChannelRange(std::span<const float> values, const std::string& source,
                       const std::string& name, float bound, const char* role);

}  // namespace amrstream::flow
