#pragma once
// Writes a uniform grid (flow::UniformGrid) as VTK XML ImageData (.vti), readable by VTK 9 and
// ParaView: WholeExtent 0..N-1 per axis, Origin the first point, Spacing the points' distance;
// point arrays the vector (Float32, 3 components, the PointData's Vectors), one Float32 array per
// channel and vtkValidPointMask (UInt8: 1 where the sample is valid), as ParaView's Resample To
// Image names it. Compressed as VTK does (zlib by default), with optional FieldData.

#include <filesystem>
#include <string>
#include <vector>

#include "flow/uniform_resample.hpp"
#include "vtk_compression.hpp"
#include "vtk_field_data.hpp"

namespace amrstream::output {

struct VtiWriteOptions {
  Compression compression = Compression::ZLib;
  std::string vectorName = "Vectors";
  std::vector<std::string> channelNames;  // one per channel of the grid
  std::vector<FieldDataArray> fieldData;
};

// Throws std::invalid_argument when the grid's arrays do not match its dims or the channel
// names, std::runtime_error naming the path when the file cannot be written (no file is left).
void writeVti(const std::filesystem::path& path, const flow::UniformGrid& grid,
              const VtiWriteOptions& options = {});

}  // namespace amrstream::output
