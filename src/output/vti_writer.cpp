#include "output/vti_writer.hpp"

#include <fmt/format.h>

#include <bit>
#include <cstring>
#include <stdexcept>

#include "output/vtk_xml_appended.hpp"

namespace amrstream::output {
namespace {

static_assert(std::endian::native == std::endian::little,
              "the file declares byte_order=\"LittleEndian\" and its values are written as in "
              "memory");

// An array whose bytes are those of `values` as they lie in memory.
AppendedArray contiguousArray(std::string name, std::string_view type, int components,
                              const void* values, std::uint64_t bytes) {
  const auto* source = static_cast<const std::byte*>(values);
  return {std::move(name),
          type,
          components,
          bytes,
          {},
          [source](std::uint64_t first, std::span<std::byte> out) {
            std::memcpy(out.data(), source + first, out.size());
          }};
}

// Channel `c` of `count` interleaved channels, as Float32.
AppendedArray channelArray(std::string name, const std::vector<float>& channels, std::size_t c,
                           std::size_t count, std::uint64_t points) {
  return {std::move(name),
          "Float32",
          1,
          points * sizeof(float),
          {},
          [&channels, c, count](std::uint64_t first, std::span<std::byte> out) {
            // Blocks cut anywhere, so go byte by byte through whole floats and their parts.
            for (std::uint64_t b = first; b < first + out.size();) {
              const std::uint64_t point = b / sizeof(float), within = b % sizeof(float);
              const float value = channels[point * count + c];
              const std::uint64_t n =
                  std::min<std::uint64_t>(sizeof(float) - within, first + out.size() - b);
              std::memcpy(out.data() + (b - first),
                          reinterpret_cast<const std::byte*>(&value) + within, n);
              b += n;
            }
          }};
}

std::string triple(const glm::dvec3& v) {
  return fmt::format("{:.17g} {:.17g} {:.17g}", v.x, v.y, v.z);
}

}  // namespace

void writeVti(const std::filesystem::path& path, const flow::UniformGrid& grid,
              const VtiWriteOptions& options) {
  const flow::UniformGridSpec& spec = grid.spec;
  const std::uint64_t points = spec.pointCount();
  const std::size_t channels = options.channelNames.size();
  if (grid.vectors.size() != points || grid.valid.size() != points ||
      grid.channels.size() != points * channels)
    throw std::invalid_argument(fmt::format(
        "cannot write '{}': a grid of {} points with {} vectors, {} channel values for {} "
        "channels and {} mask values",
        path.string(), points, grid.vectors.size(), grid.channels.size(), channels,
        grid.valid.size()));

  std::vector<AppendedArray> arrays;
  arrays.push_back(contiguousArray(options.vectorName, "Float32", 3, grid.vectors.data(),
                                   points * sizeof(glm::vec3)));
  for (std::size_t c = 0; c < channels; ++c)
    arrays.push_back(channelArray(options.channelNames[c], grid.channels, c, channels, points));
  arrays.push_back(contiguousArray("vtkValidPointMask", "UInt8", 1, grid.valid.data(), points));

  const std::string extent =
      fmt::format("0 {} 0 {} 0 {}", spec.dims[0] - 1, spec.dims[1] - 1, spec.dims[2] - 1);
  AppendedFileWriter file("ImageData", options.compression);
  if (options.frame) {
    const VtiFrame& f = *options.frame;
    std::string direction;
    for (int row = 0; row < 3; ++row)
      for (int column = 0; column < 3; ++column)
        direction += fmt::format("{}{:.17g}", direction.empty() ? "" : " ", f.axes[column][row]);
    file.markup(fmt::format(
        "  <ImageData WholeExtent=\"{}\" Origin=\"{}\" Spacing=\"{}\" Direction=\"{}\">\n", extent,
        triple(f.origin), triple(f.spacing), direction));
  } else {
    file.markup(fmt::format("  <ImageData WholeExtent=\"{}\" Origin=\"{}\" Spacing=\"{}\">\n",
                            extent, triple(spec.origin()), triple(spec.spacing())));
  }
  file.fieldData(options.fieldData, 4);
  file.markup(fmt::format("    <Piece Extent=\"{}\">\n", extent));
  file.markup(fmt::format("      <PointData Vectors=\"{}\">\n", xmlAttribute(options.vectorName)));
  for (const AppendedArray& array : arrays) file.dataArray(array, 8);
  file.markup(
      "      </PointData>\n      <CellData>\n      </CellData>\n    </Piece>\n"
      "  </ImageData>\n");
  file.write(path);
}

}  // namespace amrstream::output
