#include "value_range.hpp"

#include <fmt/format.h>

#include <cmath>

#include "util/input_error.hpp"

namespace amrstream::flow {

namespace {

void checkChannel(const bricks::AmrField& field, const std::string& name, float bound,
                  const char* role) {
  const std::vector<float>& values = field.channel(name).values;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (std::abs(values[i]) <= bound) continue;
    const glm::ivec3 corner = field.lowers()[i];
    throw InputError(
        field.source(),
        fmt::format("{} '{}' is {:g} at the cell with corner ({}, {}, {}); amrstream's float32 "
                    "arithmetic needs |values| <= {:g} there: rescale the field",
                    role, name, values[i], corner.x, corner.y, corner.z, bound));
  }
}

}  // namespace

void checkArithmeticRange(const bricks::AmrField& field, const VectorChannels& vector,
                          std::span<const std::string> pointData) {
  for (const std::string& channel : vector.channels)
    checkChannel(field, channel, kMaxVectorComponent, "the vector component");
  for (const std::string& channel : pointData)
    checkChannel(field, channel, kMaxPointDataValue, "the point-data channel");
}

}  // namespace amrstream::flow
