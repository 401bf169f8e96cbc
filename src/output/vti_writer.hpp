#pragma once
// Writes a uniform grid (flow::UniformGrid) as VTK XML ImageData (.vti), readable by VTK 9 and
// ParaView: WholeExtent 0..N-1 per axis, Origin the first point, Spacing the points' distance;
// point arrays the vector (Float32, 3 components, the PointData's Vectors), one Float32 array per
// channel and vtkValidPointMask (UInt8: 1 where the sample is valid), as ParaView's Resample To
// Image names it. Compressed as VTK does (zlib by default), with optional FieldData.

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "flow/uniform_resample.hpp"
#include "vtk_compression.hpp"
#include "vtk_field_data.hpp"

namespace amrstream::output {

// An image whose axes are not x, y and z: point (i, j, k) at origin + i spacing.x axes[0] +
// j spacing.y axes[1] + k spacing.z axes[2] (VTK's Direction matrix, whose columns are the axes).
struct VtiFrame {
  glm::dvec3 origin{0.0}, spacing{1.0};
  std::array<glm::dvec3, 3> axes{glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0), glm::dvec3(0, 0, 1)};
};

struct VtiWriteOptions {
  Compression compression = Compression::ZLib;
  // In place of the grid's box: the image's frame, written with its Direction.
  std::optional<VtiFrame> frame;
  std::string vectorName = "Vectors";
  std::vector<std::string> channelNames;  // one per channel of the grid
  std::vector<FieldDataArray> fieldData;
};

// Throws std::invalid_argument when the grid's arrays do not match its dims or the channel
// names, std::runtime_error naming the path when the file cannot be written (no file is left).
void writeVti(const std::filesystem::path& path, const flow::UniformGrid& grid,
              const VtiWriteOptions& options = {});

}  // namespace amrstream::output
