#include "formats/enzo/enzo_writer.hpp"

#include <fmt/format.h>

#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "amrstream/error.hpp"
#include "formats/box_geometry.hpp"
#include "formats/hdf5_writing.hpp"
#include "formats/leaf_boxes.hpp"
#include "formats/staged_outputs.hpp"

namespace amrstream::formats {

namespace {

namespace fs = std::filesystem;

// Grids per field file: a new file once one holds this many bytes of values.
constexpr std::uint64_t kFieldFileBytes = std::uint64_t(256) << 20;
// Enzo's boundary condition number for periodic faces, and for outflow.
constexpr int kPeriodic = 3, kOutflow = 1;

std::string triple(glm::dvec3 v) { return fmt::format("{:.17g} {:.17g} {:.17g}", v.x, v.y, v.z); }
std::string triple(glm::ivec3 v) { return fmt::format("{} {} {}", v.x, v.y, v.z); }

// Field file of each grid: PREFIX.cpuNNNN, filled in grid order.
std::vector<int> fieldFiles(const LeafBoxes& boxes, std::size_t channels) {
  std::vector<int> files;
  int file = 0;
  std::uint64_t bytes = 0;
  for (const LeafBox& box : boxes.boxes()) {
    if (bytes >= kFieldFileBytes) ++file, bytes = 0;
    files.push_back(file);
    bytes += std::uint64_t(box.cells.x) * box.cells.y * box.cells.z * channels * 4;
  }
  return files;
}

void writeFieldFile(const fs::path& path, const std::string& name, const bricks::AmrField& field,
                    const LeafBoxes& boxes, const std::vector<int>& files, int file) {
  Hdf5Writing out(path, name);
  std::vector<float> values;
  for (std::size_t g = 0; g < boxes.boxes().size(); ++g) {
    if (files[g] != file) continue;
    const glm::ivec3 n = boxes.boxes()[g].cells;
    const Hdf5Handle group = out.group(fmt::format("Grid{:08d}", g + 1));
    values.resize(std::size_t(n.x) * n.y * n.z);
    const hsize_t dims[] = {hsize_t(n.z), hsize_t(n.y), hsize_t(n.x)};
    for (const Channel& channel : field.channels()) {
      boxes.gather(g, channel.values, values.data());
      out.array(group.get(), channel.name, dims, H5T_NATIVE_FLOAT, H5T_IEEE_F32LE, values.data());
    }
  }
  out.close();
}

std::string hierarchyText(const bricks::AmrField& field, const LeafBoxes& boxes,
                          const std::vector<int>& files, const std::string& prefixName) {
  const std::vector<LeafBox>& grids = boxes.boxes();
  std::map<int, std::size_t> lastOnLevel;  // to link each grid to the next of its level
  std::vector<std::size_t> nextThisLevel(grids.size(), 0);
  for (std::size_t g = grids.size(); g-- > 0;) {
    const auto it = lastOnLevel.find(grids[g].level);
    if (it != lastOnLevel.end()) nextThisLevel[g] = it->second + 1;
    lastOnLevel[grids[g].level] = g;
  }
  std::string text;
  for (std::size_t g = 0; g < grids.size(); ++g) {
    const LeafBox& grid = grids[g];
    const glm::dvec3 lo = BoxGeometry::physical(field, grid.lower);
    const glm::dvec3 hi = BoxGeometry::physical(field, grid.lower + (grid.cells << grid.level));
    text += fmt::format(
        "\nGrid = {}\nTask = {}\nGridRank = 3\nGridDimension = {}\nGridStartIndex = 3 3 3\n"
        "GridEndIndex = {}\nGridLeftEdge = {}\nGridRightEdge = {}\nTime = {:.17g}\n"
        "NumberOfBaryonFields = {}\nBaryonFileName = {}.cpu{:04d}\nNumberOfParticles = 0\n"
        "Pointer: Grid[{}]->NextGridThisLevel = {}\nPointer: Grid[{}]->NextGridNextLevel = 0\n",
        g + 1, files[g], triple(grid.cells + 6), triple(grid.cells + 2), triple(lo), triple(hi),
        field.info().time.value_or(0.0), field.channels().size(), prefixName, files[g], g + 1,
        nextThisLevel[g], g + 1);
  }
  return text;
}

std::string parameterText(const bricks::AmrField& field, const BoxGeometry& geometry) {
  const DatasetInfo& info = field.info();
  const glm::ivec3 domainCells = geometry.domainCells;
  std::string boundary;
  for (int a = 0; a < 3; ++a)
    boundary += fmt::format("{}{}", a ? " " : "", info.periodic[a] ? kPeriodic : kOutflow);
  std::string text = fmt::format(
      "InitialTime = {:.17g}\nInitialCycleNumber = 0\nTopGridRank = 3\nTopGridDimensions = {}\n"
      "DomainLeftEdge = {}\nDomainRightEdge = {}\nRefineBy = 2\nMaximumRefinementLevel = {}\n"
      "ComovingCoordinates = 0\n",
      info.time.value_or(0.0), triple(domainCells),
      triple(BoxGeometry::physical(field, glm::ivec3(0))),
      triple(BoxGeometry::physical(field, domainCells << geometry.coarsest)),
      geometry.coarsest - geometry.finest);
  if (info.periodicKnown)
    text += fmt::format("LeftFaceBoundaryCondition = {}\nRightFaceBoundaryCondition = {}\n",
                        boundary, boundary);
  return text;
}

void writeText(const fs::path& path, const std::string& name, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  out.close();
  if (!out) throw InputError(name, "cannot write it (disk full?)");
}

}  // namespace

void writeEnzo(const bricks::AmrField& field, const fs::path& prefix) {
  if (field.info().dimensions != 3)
    throw InputError(prefix.string(), "only 3D cells are written as Enzo outputs");
  const LeafBoxes boxes(field, 8);
  const BoxGeometry geometry(field, boxes);
  const std::vector<int> files = fieldFiles(boxes, field.channels().size());
  const std::string prefixName = prefix.filename().string();
  StagedOutputs outputs;
  for (int file = 0; file <= (files.empty() ? -1 : files.back()); ++file) {
    const fs::path path = fmt::format("{}.cpu{:04d}", prefix.string(), file);
    writeFieldFile(outputs.stage(path), path.string(), field, boxes, files, file);
  }
  const fs::path hierarchy = prefix.string() + ".hierarchy";
  writeText(outputs.stage(hierarchy), hierarchy.string(),
            hierarchyText(field, boxes, files, prefixName));
  writeText(outputs.stage(prefix), prefix.string(), parameterText(field, geometry));
  outputs.commit();
}

}  // namespace amrstream::formats
