#include "formats/amrex/amrex_writer.hpp"

#include <fmt/format.h>

#include <fstream>
#include <string>
#include <vector>

#include "amrstream/error.hpp"
#include "formats/box_geometry.hpp"
#include "formats/leaf_boxes.hpp"
#include "formats/staged_outputs.hpp"

namespace amrstream::formats {

namespace {

namespace fs = std::filesystem;

// FABs per Cell_D file: a new file once one holds this many bytes.
constexpr std::uint64_t kCellDataBytes = std::uint64_t(256) << 20;

struct LevelBox {
  std::size_t box;    // among the leaf boxes
  glm::ivec3 lo, hi;  // in the level's cells, inclusive
};

std::string boxText(glm::ivec3 lo, glm::ivec3 hi) {
  return fmt::format("(({},{},{}) ({},{},{}) (0,0,0))", lo.x, lo.y, lo.z, hi.x, hi.y, hi.z);
}

// Per AMReX level (0 = the coarsest leaves), its boxes.
std::vector<std::vector<LevelBox>> levelBoxes(const LeafBoxes& boxes, const BoxGeometry& geometry,
                                              const fs::path& directory) {
  std::vector<std::vector<LevelBox>> levels(std::size_t(geometry.coarsest - geometry.finest + 1));
  for (std::size_t b = 0; b < boxes.boxes().size(); ++b) {
    const LeafBox& box = boxes.boxes()[b];
    const glm::ivec3 lo = box.lower >> box.level;
    levels[std::size_t(geometry.coarsest - box.level)].push_back({b, lo, lo + box.cells - 1});
  }
  for (std::size_t l = 0; l < levels.size(); ++l)
    if (levels[l].empty())
      throw InputError(directory.string(),
                       fmt::format("AMReX level {} would have no boxes: no leaf cells are that "
                                   "fine",
                                   l));
  return levels;
}

class TextFile {
 public:
  TextFile(const fs::path& path, std::string name) : out_(path, std::ios::binary), name_(name) {
    if (!out_) throw InputError(name_, "cannot create it");
  }
  std::ofstream& out() { return out_; }
  void close() {
    out_.close();
    if (!out_) throw InputError(name_, "cannot write it (disk full?)");
  }

 private:
  std::ofstream out_;
  std::string name_;
};

// Level_L/Cell_D_* and Level_L/Cell_H.
void writeLevel(const fs::path& directory, const fs::path& name, int l,
                const std::vector<LevelBox>& boxes, const bricks::AmrField& field,
                const LeafBoxes& leafBoxes) {
  const fs::path level = directory / fmt::format("Level_{}", l);
  fs::create_directories(level);
  const std::size_t ncomp = field.channels().size();
  std::string cellH = fmt::format("1\n0\n{}\n0\n({} 0\n", ncomp, boxes.size());
  for (const LevelBox& box : boxes) cellH += boxText(box.lo, box.hi) + "\n";
  cellH += fmt::format(")\n{}\n", boxes.size());
  std::vector<float> values;
  int file = -1;
  std::optional<TextFile> data;
  for (const LevelBox& box : boxes) {
    if (!data || std::uint64_t(data->out().tellp()) >= kCellDataBytes) {
      if (data) data->close();
      ++file;
      data.emplace(level / fmt::format("Cell_D_{:05d}", file),
                   (name / fmt::format("Level_{}/Cell_D_{:05d}", l, file)).string());
    }
    cellH += fmt::format("FabOnDisk: Cell_D_{:05d} {}\n", file, std::uint64_t(data->out().tellp()));
    data->out() << "FAB ((4, (32 8 23 0 1 9 0 127)),(4, (4 3 2 1)))" << boxText(box.lo, box.hi)
                << ' ' << ncomp << '\n';
    const glm::ivec3 n = box.hi - box.lo + 1;
    const std::size_t cells = std::size_t(n.x) * n.y * n.z;
    values.resize(cells);
    for (const Channel& channel : field.channels()) {
      leafBoxes.gather(box.box, channel.values, values.data());
      data->out().write(reinterpret_cast<const char*>(values.data()),
                        std::streamsize(cells * sizeof(float)));
    }
  }
  if (data) data->close();
  TextFile header(level / "Cell_H", (name / fmt::format("Level_{}/Cell_H", l)).string());
  header.out() << cellH;
  header.close();
}

std::string headerText(const bricks::AmrField& field, const BoxGeometry& geometry,
                       const std::vector<std::vector<LevelBox>>& levels,
                       const LeafBoxes& leafBoxes) {
  const DatasetInfo& info = field.info();
  const int finest = int(levels.size()) - 1;
  const glm::dvec3 lo = BoxGeometry::physical(field, glm::ivec3(0));
  const glm::dvec3 hi = BoxGeometry::physical(field, geometry.domainCells << geometry.coarsest);
  std::string text = fmt::format("HyperCLaw-V1.1\n{}\n", field.channels().size());
  for (const Channel& channel : field.channels()) text += channel.name + "\n";
  text += fmt::format("3\n{:.17g}\n{}\n{:.17g} {:.17g} {:.17g}\n{:.17g} {:.17g} {:.17g}\n",
                      info.time.value_or(0.0), finest, lo.x, lo.y, lo.z, hi.x, hi.y, hi.z);
  for (int l = 0; l < finest; ++l) text += "2 ";
  text += "\n";
  for (int l = 0; l <= finest; ++l)
    text += boxText(glm::ivec3(0), (geometry.domainCells << l) - 1) + " ";
  text += "\n";
  for (int l = 0; l <= finest; ++l) text += "0 ";
  text += "\n";
  for (int l = 0; l <= finest; ++l) {
    const glm::dvec3 dx = (hi - lo) / glm::dvec3(geometry.domainCells << l);
    text += fmt::format("{:.17g} {:.17g} {:.17g}\n", dx.x, dx.y, dx.z);
  }
  text += "0\n0\n";
  for (int l = 0; l <= finest; ++l) {
    text += fmt::format("{} {} {:.17g}\n0\n", l, levels[l].size(), info.time.value_or(0.0));
    for (const LevelBox& box : levels[l]) {
      const LeafBox& leaf = leafBoxes.boxes()[box.box];
      const glm::dvec3 boxLo = BoxGeometry::physical(field, leaf.lower);
      const glm::dvec3 boxHi =
          BoxGeometry::physical(field, leaf.lower + (leaf.cells << leaf.level));
      for (int a = 0; a < 3; ++a) text += fmt::format("{:.17g} {:.17g}\n", boxLo[a], boxHi[a]);
    }
    text += fmt::format("Level_{}/Cell\n", l);
  }
  return text;
}

}  // namespace

void writeAmrexPlotfile(const bricks::AmrField& field, const fs::path& directory) {
  if (field.info().dimensions != 3)
    throw InputError(directory.string(), "only 3D cells are written as AMReX plotfiles");
  const LeafBoxes boxes(field, 8);
  const BoxGeometry geometry(field, boxes);
  const auto levels = levelBoxes(boxes, geometry, directory);
  StagedOutputs outputs;
  const fs::path staged = outputs.stage(directory);
  std::error_code error;
  if (!fs::create_directory(staged, error))
    throw InputError(directory.string(), fmt::format("cannot create it: {}", error.message()));
  for (std::size_t l = 0; l < levels.size(); ++l)
    writeLevel(staged, directory, int(l), levels[l], field, boxes);
  TextFile header(staged / "Header", (directory / "Header").string());
  header.out() << headerText(field, geometry, levels, boxes);
  header.close();
  outputs.commit();
}

}  // namespace amrstream::formats
