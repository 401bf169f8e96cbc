// The C++ side of the headers shared with GLSL: GLSL's vector and scalar type names as glm and
// <cstdint> types in amrstream::shared. The shared headers include this under __cplusplus.
#ifndef AMRSTREAM_SHARED_GLSL_COMPAT_H
#define AMRSTREAM_SHARED_GLSL_COMPAT_H

#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>

namespace amrstream::shared {
using vec3 = glm::vec3;
using vec4 = glm::vec4;
using uvec2 = glm::uvec2;
using uvec3 = glm::uvec3;
using ivec3 = glm::ivec3;
using uint = std::uint32_t;
}  // namespace amrstream::shared

#endif
