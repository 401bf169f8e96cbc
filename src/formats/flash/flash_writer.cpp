#include "formats/flash/flash_writer.hpp"

#include <tbb/parallel_for.h>

#include <string>
#include <utility>
#include <vector>

#include "amrstream/error.hpp"
#include "formats/box_geometry.hpp"
#include "formats/hdf5_writing.hpp"
#include "formats/leaf_boxes.hpp"
#include "formats/staged_outputs.hpp"

namespace amrstream::formats {

namespace {

using Pairs = std::vector<std::pair<std::string, int>>;

// The blocks' places: refine level, bounding box, size and centre.
void writeBlocks(const Hdf5Writing& out, const bricks::AmrField& field, const LeafBoxes& boxes,
                 const BoxGeometry& geometry) {
  const std::vector<LeafBox>& blocks = boxes.boxes();
  const hsize_t nb = blocks.size();
  std::vector<int> refine, nodeType(nb, 1), gid(nb * 15, -1);
  std::vector<double> bbox, size, centre;
  for (const LeafBox& block : blocks) {
    refine.push_back(geometry.coarsest - block.level + 1);
    const glm::dvec3 lo = BoxGeometry::physical(field, block.lower);
    const glm::dvec3 hi = BoxGeometry::physical(field, block.lower + (block.cells << block.level));
    for (int a = 0; a < 3; ++a) {
      bbox.insert(bbox.end(), {lo[a], hi[a]});
      size.push_back(hi[a] - lo[a]);
      centre.push_back(0.5 * (lo[a] + hi[a]));
    }
  }
  const hsize_t one[] = {nb}, three[] = {nb, 3}, box[] = {nb, 3, 2}, links[] = {nb, 15};
  out.array(out.root(), "refine level", one, H5T_NATIVE_INT, H5T_STD_I32LE, refine.data());
  out.array(out.root(), "node type", one, H5T_NATIVE_INT, H5T_STD_I32LE, nodeType.data());
  out.array(out.root(), "gid", links, H5T_NATIVE_INT, H5T_STD_I32LE, gid.data());
  out.array(out.root(), "bounding box", box, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE, bbox.data());
  out.array(out.root(), "block size", three, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE, size.data());
  out.array(out.root(), "coordinates", three, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE, centre.data());
}

void writeParameters(const Hdf5Writing& out, const bricks::AmrField& field, const LeafBoxes& boxes,
                     const BoxGeometry& geometry) {
  const int side = boxes.side();
  const int blocks = static_cast<int>(boxes.boxes().size());
  const DatasetInfo& info = field.info();
  out.pairs<int>("integer scalars", Pairs{{"nxb", side},
                                          {"nyb", side},
                                          {"nzb", side},
                                          {"dimensionality", 3},
                                          {"globalnumblocks", blocks},
                                          {"nstep", 0}});
  const glm::ivec3 rootBlocks = (geometry.domainCells + side - 1) / side;
  out.pairs<int>("integer runtime parameters",
                 Pairs{{"lrefine_min", 1},
                       {"lrefine_max", geometry.coarsest - geometry.finest + 1},
                       {"nblockx", rootBlocks.x},
                       {"nblocky", rootBlocks.y},
                       {"nblockz", rootBlocks.z}});
  out.pairs<double>("real scalars", {{"time", info.time.value_or(0.0)}});
  const glm::dvec3 lo = BoxGeometry::physical(field, glm::ivec3(0));
  const glm::dvec3 hi = BoxGeometry::physical(field, rootBlocks * (side << geometry.coarsest));
  out.pairs<double>("real runtime parameters", {{"xmin", lo.x},
                                                {"xmax", hi.x},
                                                {"ymin", lo.y},
                                                {"ymax", hi.y},
                                                {"zmin", lo.z},
                                                {"zmax", hi.z}});
  std::vector<std::pair<std::string, std::string>> strings{{"geometry", "cartesian"}};
  // FLASH assumes CGS without pc_unitsbase: say so only of centimetres and metres.
  const std::string& unit = info.lengthUnit;
  strings.emplace_back("pc_unitsbase", unit == "cm" ? "CGS" : unit == "m" ? "MKS" : "none");
  if (info.periodicKnown)
    for (int a = 0; a < 3; ++a)
      for (const char* side : {"l", "r"})
        strings.emplace_back(std::string(1, "xyz"[a]) + side + "_boundary_type",
                             info.periodic[a] ? "periodic" : "outflow");
  out.pairs<std::string>("string runtime parameters", strings);
  const int version = 9;
  const hsize_t one[] = {1};
  out.array(out.root(), "file format version", one, H5T_NATIVE_INT, H5T_STD_I32LE, &version);
}

void writeVariables(const Hdf5Writing& out, const bricks::AmrField& field, const LeafBoxes& boxes) {
  const std::size_t nb = boxes.boxes().size();
  const hsize_t side = hsize_t(boxes.side());
  const std::size_t perBlock = side * side * side;
  std::vector<std::string> names;
  for (const Channel& channel : field.channels()) names.push_back(channel.name);
  out.strings("unknown names", names);
  std::vector<float> values(nb * perBlock);
  for (const Channel& channel : field.channels()) {
    tbb::parallel_for(std::size_t(0), nb, [&](std::size_t b) {
      boxes.gather(b, channel.values, values.data() + b * perBlock);
    });
    const hsize_t dims[] = {nb, side, side, side};
    out.array(out.root(), channel.name, dims, H5T_NATIVE_FLOAT, H5T_IEEE_F32LE, values.data());
  }
}

}  // namespace

void writeFlash(const bricks::AmrField& field, const std::filesystem::path& path) {
  if (field.info().dimensions != 3)
    throw InputError(path.string(), "only 3D cells are written as FLASH files");
  const LeafBoxes boxes(field, 1);
  const BoxGeometry geometry(field, boxes);
  StagedOutputs outputs;
  Hdf5Writing out(outputs.stage(path), path.string());
  writeVariables(out, field, boxes);
  writeBlocks(out, field, boxes, geometry);
  writeParameters(out, field, boxes, geometry);
  out.close();
  outputs.commit();
}

}  // namespace amrstream::formats
