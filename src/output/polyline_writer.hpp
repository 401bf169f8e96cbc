#pragma once
// Polylines with point arrays as VTK XML PolyData (.vtp): a slice's field lines, which carry no
// integration time or termination reason as traces do (vtp_writer.hpp writes those).

#include <cstdint>
#include <filesystem>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "output/vtk_compression.hpp"
#include "output/vtk_field_data.hpp"

namespace amrstream::output {

struct PolylineArray {
  std::string name;
  int components = 1;
  std::vector<float> values;  // components per point
};

struct Polylines {
  std::vector<glm::vec3> points;
  std::vector<std::uint64_t> offsets{0};  // line i: points [offsets[i], offsets[i + 1])
  std::vector<PolylineArray> pointData;
  std::string scalars, vectors;  // the arrays ParaView colours by first; may be empty
};

struct PolylineWriteOptions {
  Compression compression = Compression::ZLib;
  std::vector<FieldDataArray> fieldData;
};

// Throws std::invalid_argument before creating the file when the offsets or an array's size do
// not match the points, or a line has fewer than 2 points (VTK rejects them); std::runtime_error
// naming the path when the file cannot be written (no file is left).
void writePolylines(const std::filesystem::path& path, const Polylines& lines,
                    const PolylineWriteOptions& options = {});

}  // namespace amrstream::output
