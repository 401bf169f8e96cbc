// Writes the seed corpora, fuzz/corpus/NAME/, from the project's own writers and small hand-made
// samples; with a second argument, the directory of the real data sets, it adds small pieces of
// those files too. Every synthetic seed that should read is read back here first, so a corpus
// that only reaches an early error is noticed when it is made.
//
// Usage: fuzz_make_corpus CORPUS_DIR [REAL_DATA_DIR]

#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "amrstream/error.hpp"
#include "flow/seeds.hpp"
#include "formats/amrex/amrex_reader.hpp"
#include "formats/enzo/enzo_reader.hpp"
#include "formats/exa/exa_format.hpp"
#include "formats/flash/flash_reader.hpp"
#include "formats/gerris/gerris_reader.hpp"
#include "formats/hdf5_handle.hpp"
#include "fuzz_files.hpp"
#include "hdf5_recipe.hpp"
#include "output/seed_file_writer.hpp"
#include "output/vtp_writer.hpp"
#include "random_amr.hpp"

namespace amrstream::fuzz {
namespace {

namespace fs = std::filesystem;

std::string readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

void writeSeed(const fs::path& corpus, const std::string& harness, const std::string& name,
               const std::string& bytes) {
  fs::create_directories(corpus / harness);
  std::ofstream(corpus / harness / name, std::ios::binary) << bytes;
  std::printf("%-6s %-28s %6zu bytes\n", harness.c_str(), name.c_str(), bytes.size());
}

// Reads a seed's files as the harness would and says whether the reader accepted them.
void check(const std::string& seed, const std::function<void()>& read) {
  try {
    read();
    std::printf("  %s: read\n", seed.c_str());
  } catch (const InputError& e) {
    std::printf("  %s: refused: %s\n", seed.c_str(), e.what());
  }
}

// ---- ExaBricks -------------------------------------------------------------------------------

void exaSeeds(const fs::path& corpus, const fs::path& scratch) {
  testing::RandomAmrOptions options;
  options.levels = 2;
  options.rootCells = {2, 1, 1};
  const bricks::AmrField random = testing::randomAmr(11, options);
  const auto values = [&](std::size_t c) { return random.channels()[c].values; };
  bricks::AmrField field({random.lowers().begin(), random.lowers().end()},
                         {random.levels().begin(), random.levels().end()},
                         {{"u", values(0)}, {"v", values(1)}}, {{0.5, -1, 2}, {0.25, 0.25, 0.5}},
                         "seed");
  DatasetInfo info;
  info.time = 2.5;
  info.periodic = {true, false, true};
  info.periodicKnown = true;
  info.lengthUnit = "cm";
  field.setInfo(info);
  const fs::path exa = formats::writeExa(field, scratch / "a");
  check("exa written", [&] { formats::readExa(exa); });
  const auto file = [&](const char* name) { return readFile(scratch / name); };
  writeSeed(corpus, "exa", "written",
            joinParts({file("a.exa"), file("a.cells"), file("a.u.scalars"), file("a.v.scalars")}));

  const auto cells = [](const std::vector<std::array<std::int32_t, 4>>& list) {
    return std::string(reinterpret_cast<const char*>(list.data()), list.size() * 16);
  };
  const std::string twoFloats("\0\0\x80\x3f\0\0\0\x40", 8);  // 1.0f, 2.0f
  writeSeed(corpus, "exa", "hand_made",
            joinParts({"# two cells\ncells a.cells\nscalar u a.u.scalars\nbricks x.bricks\n"
                       "origin 0 0 0\nspacing 1 1 1\ntime 1.5\nperiodic 1 0 1\n"
                       "length-unit Mpc / h\ntime-unit Gyr\n",
                       cells({{0, 0, 0, 0}, {1, 0, 0, 0}}), twoFloats}));
  writeSeed(corpus, "exa", "int_max_corner",
            joinParts({"cells a.cells\nscalar u a.u.scalars\n",
                       cells({{0, 0, 0, 0}, {2147483647, 0, 0, 0}}), twoFloats}));
  writeSeed(corpus, "exa", "huge_transform",
            joinParts({"cells a.cells\nscalar u a.u.scalars\norigin 1e308 0 0\nspacing 1e-320 1 "
                       "1\n",
                       cells({{0, 0, 0, 0}, {1, 0, 0, 0}}), twoFloats}));
}

// ---- Gerris ----------------------------------------------------------------------------------

void gerrisSeeds(const fs::path& corpus, const fs::path& scratch, const fs::path& real) {
  std::ostringstream dump;
  dump.precision(9);
  dump << "# 1:x 2:y 3:z 4:U 5:V 6:W 7:Lev 0.25\n";
  for (int n = 0; n < 8; ++n) {
    const glm::dvec3 c = glm::dvec3(n & 1, (n >> 1) & 1, n >> 2) * 0.5 - 0.25;
    if (n == 0) {
      for (int m = 0; m < 8; ++m) {
        const glm::dvec3 f = glm::dvec3(m & 1, (m >> 1) & 1, m >> 2) * 0.25 - 0.375;
        dump << f.x << ' ' << f.y << ' ' << f.z << ' ' << f.x + f.y << " 1 " << -f.z << " 2\n";
      }
      continue;
    }
    dump << c.x << ' ' << c.y << ' ' << c.z << ' ' << c.x + c.y << " 1 " << -c.z << " 1\n";
  }
  std::ofstream(scratch / "dump.txt") << dump.str();
  check("gerris two levels", [&] { formats::readGerris(scratch / "dump.txt"); });
  writeSeed(corpus, "gerris", "two_levels", dump.str());
  writeSeed(corpus, "gerris", "columns_reordered",
            "# 1:Lev 2:P 3:z 4:y 5:x 6:T 1.5\n0 7 0 0 0 -2\n0 8 0 0 1 -3\n");
  writeSeed(corpus, "gerris", "not_finite", "# 1:x 2:y 3:z 4:U 5:Lev\n0 0 0 nan 0\n1 0 0 inf 0\n");

  const fs::path ring = real / "gerris-ring" / "ring-end.txt";
  if (fs::exists(ring)) {
    std::ifstream in(ring);
    std::string head, line;
    for (int n = 0; n < 40 && std::getline(in, line); ++n) head += line + "\n";
    writeSeed(corpus, "gerris", "real_ring_head", head);
  }
}

// ---- AMReX -----------------------------------------------------------------------------------

struct Box {
  glm::ivec3 lo, hi;
};

std::string boxText(const Box& b) {
  std::ostringstream out;
  out << "((" << b.lo.x << ',' << b.lo.y << ',' << b.lo.z << ") (" << b.hi.x << ',' << b.hi.y << ','
      << b.hi.z << ") (0,0,0))";
  return out.str();
}

std::string fab(const Box& b, bool float32) {
  std::string text = std::string("FAB (") +
                     (float32 ? "(4, (32 8 23 0 1 9 0 127)),(4, (4 3 2 1))"
                              : "(8, (64 11 52 0 1 12 0 1023)),(8, (8 7 6 5 4 3 2 1))") +
                     ")" + boxText(b) + " 2\n";
  for (int c = 0; c < 2; ++c)
    for (int k = b.lo.z; k <= b.hi.z; ++k)
      for (int j = b.lo.y; j <= b.hi.y; ++j)
        for (int i = b.lo.x; i <= b.hi.x; ++i) {
          const double v = c == 0 ? i + 2.0 * j - k : 0.5 * i * j;
          if (float32) {
            const float f = float(v);
            text.append(reinterpret_cast<const char*>(&f), 4);
          } else {
            text.append(reinterpret_cast<const char*>(&v), 8);
          }
        }
  return text;
}

// Level 0: (0..3)^3 in one box; level 1 refines coarse cells (1..2)^3 with one box.
std::vector<std::string> plotfileParts(bool float32) {
  const Box coarse{{0, 0, 0}, {3, 3, 3}}, fine{{2, 2, 2}, {5, 5, 5}};
  const std::string header =
      "HyperCLaw-V1.1\n2\nA\nB\n3\n0.5\n1\n0 0 0\n1 1 1\n2\n"
      "((0,0,0) (3,3,3) (0,0,0)) ((0,0,0) (7,7,7) (0,0,0))\n0 0\n0.25 0.25 0.25\n"
      "0.125 0.125 0.125\n0\n0\n0 1 0.5\n0\n0 1\n0 1\n0 1\nLevel_0/Cell\n"
      "1 1 0.5\n0\n0.25 0.75\n0.25 0.75\n0.25 0.75\nLevel_1/Cell\n";
  const auto cellH = [](const Box& b) {
    return "1\n1\n2\n0\n(1 0\n" + boxText(b) + "\n)\n1\nFabOnDisk: Cell_D_00000 0\n";
  };
  return {header,      cellH(coarse),      fab(coarse, float32),
          cellH(fine), fab(fine, float32), "geometry.is_periodic = 1 0 1\n"};
}

void amrexSeeds(const fs::path& corpus, const fs::path& scratch, const fs::path& real) {
  for (const bool float32 : {false, true}) {
    const auto parts = plotfileParts(float32);
    const char* names[] = {"Header",         "Level_0/Cell_H",       "Level_0/Cell_D_00000",
                           "Level_1/Cell_H", "Level_1/Cell_D_00000", "job_info"};
    const fs::path plt = scratch / (float32 ? "plt32" : "plt64");
    for (std::size_t i = 0; i < parts.size(); ++i) writePart(plt, names[i], parts[i]);
    check(plt.filename().string(), [&] { formats::readAmrexPlotfile(plt); });
    writeSeed(corpus, "amrex", float32 ? "two_levels_float32" : "two_levels", joinParts(parts));
  }
  const fs::path plotfile = real / "amrex-pelelmex-3d" / "example_plt_3d";
  if (fs::exists(plotfile))
    writeSeed(
        corpus, "amrex", "real_headers",
        joinParts({readFile(plotfile / "Header"), readFile(plotfile / "Level_0" / "Cell_H")}));
}

// ---- FLASH -----------------------------------------------------------------------------------

std::string fixedWidth(const std::string& text, std::size_t width, char pad) {
  std::string s = text;
  s.resize(width, pad);
  return s;
}

template <typename T>
std::string pairs(const std::vector<std::pair<std::string, T>>& list) {
  std::string bytes;
  for (const auto& [name, value] : list) {
    bytes += fixedWidth(name, 80, ' ');
    bytes.append(reinterpret_cast<const char*>(&value), sizeof value);
  }
  return bytes;
}

struct FlashSeed {
  int dim = 3;
  StringPad namePad = StringPad::kNullTerminated;
  bool variableNames = false;
  bool metadata = true;
};

// A root block (node type 2) with 2^dim leaf children, 2 cells per block axis, two variables.
std::string flashRecipe(const FlashSeed& seed) {
  const int children = 1 << seed.dim, nb = 1 + children;
  const int nz = seed.dim == 3 ? 2 : 1;
  RecipeWriter r;
  const std::vector<std::string> names{"velx", "dens"};
  if (seed.variableNames) {
    std::string data;
    for (const std::string& name : names) data += char(name.size()) + name;
    r.dataset("unknown names", RecipeType::kVariableString, {2, 1}, data);
  } else {
    r.dataset("unknown names", RecipeType::kFixedString, {2, 1},
              fixedWidth("velx", 4, '\0') + fixedWidth("dens", 4, '\0'), RecipeLayout::kContiguous,
              4, seed.namePad);
  }
  std::vector<int> refine{1}, nodeType{2};
  std::vector<double> bbox{0, 1, 0, 1, seed.dim == 3 ? 0.0 : 0.5, seed.dim == 3 ? 1.0 : 0.5};
  std::vector<double> size{1, 1, seed.dim == 3 ? 1.0 : 0.0};
  for (int c = 0; c < children; ++c) {
    refine.push_back(2);
    nodeType.push_back(1);
    for (int a = 0; a < 3; ++a) {
      const double lo = a < seed.dim ? 0.5 * ((c >> a) & 1) : 0.5;
      const double hi = a < seed.dim ? lo + 0.5 : 0.5;
      bbox.insert(bbox.end(), {lo, hi});
      size.push_back(hi - lo);
    }
  }
  const std::uint64_t n = nb;
  r.dataset("refine level", RecipeType::kInt32Le, {n}, littleEndianBytes(refine));
  r.dataset("node type", RecipeType::kInt32Le, {n}, littleEndianBytes(nodeType));
  r.dataset("bounding box", RecipeType::kFloat64Le, {n, 3, 2}, littleEndianBytes(bbox));
  r.dataset("block size", RecipeType::kFloat64Le, {n, 3}, littleEndianBytes(size));
  if (seed.metadata) {
    r.dataset(
        "integer scalars", RecipeType::kPairFixedInt, {4},
        pairs<std::int32_t>({{"nxb", 2}, {"nyb", 2}, {"nzb", nz}, {"dimensionality", seed.dim}}),
        RecipeLayout::kContiguous, 80);
    r.dataset("real scalars", RecipeType::kPairFixedDouble, {2},
              pairs<double>({{"time", 0.125}, {"dt", 1e-3}}), RecipeLayout::kContiguous, 80);
    std::string strings;
    for (const auto& [key, value] :
         std::vector<std::pair<std::string, std::string>>{{"xl_boundary_type", "periodic"},
                                                          {"xr_boundary_type", "periodic"},
                                                          {"pc_unitsbase", "CGS"}})
      strings += fixedWidth(key, 80, ' ') + fixedWidth(value, 80, ' ');
    r.dataset("string runtime parameters", RecipeType::kPairFixedFixed, {3}, strings,
              RecipeLayout::kContiguous, 80);
  }
  const std::uint64_t cells = 2 * 2 * nz;
  for (const std::string& name : names) {
    std::vector<double> values;
    for (int b = 0; b < nb; ++b)
      for (std::uint64_t i = 0; i < cells; ++i) values.push_back(b + 0.25 * double(i));
    r.dataset(name, RecipeType::kFloat64Le, {n, std::uint64_t(nz), 2, 2}, littleEndianBytes(values),
              seed.dim == 3 ? RecipeLayout::kChunked : RecipeLayout::kContiguous);
  }
  return r.bytes();
}

// The {name, value} list `name` of `file` as recipe data: its first `limit` entries, converted to
// 80-character names and T values (a fixed-length string of 80 for std::string).
std::string realPairs(hid_t file, const char* name, hid_t valueType, std::size_t valueBytes,
                      std::size_t limit, std::uint64_t& count) {
  using formats::Hdf5Handle;
  const Hdf5Handle set(H5Dopen2(file, name, H5P_DEFAULT), H5Dclose);
  if (!set.valid()) return "";
  const Hdf5Handle space(H5Dget_space(set.get()), H5Sclose);
  count = std::min<std::uint64_t>(H5Sget_simple_extent_npoints(space.get()), limit);
  const Hdf5Handle text(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(text.get(), 80);
  H5Tset_strpad(text.get(), H5T_STR_SPACEPAD);
  const Hdf5Handle memory(H5Tcreate(H5T_COMPOUND, 80 + valueBytes), H5Tclose);
  H5Tinsert(memory.get(), "name", 0, text.get());
  H5Tinsert(memory.get(), "value", 80, valueType);
  std::string all(H5Sget_simple_extent_npoints(space.get()) * (80 + valueBytes), '\0');
  if (H5Dread(set.get(), memory.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, all.data()) < 0) return "";
  return all.substr(0, count * (80 + valueBytes));
}

void flashSeeds(const fs::path& corpus, const fs::path& scratch, const fs::path& real) {
  const std::vector<std::pair<std::string, FlashSeed>> seeds{
      {"tree_3d", {}},
      {"tree_2d", {.dim = 2}},
      {"names_null_padded", {.namePad = StringPad::kNullPadded}},
      {"names_space_padded_2d", {.dim = 2, .namePad = StringPad::kSpacePadded}},
      {"names_variable_length", {.variableNames = true}},
      {"no_metadata", {.metadata = false}}};
  for (const auto& [name, seed] : seeds) {
    const std::string recipe = flashRecipe(seed);
    const fs::path file = scratch / (name + "_hdf5_plt_cnt_0000");
    writeRecipeFile({reinterpret_cast<const std::uint8_t*>(recipe.data()), recipe.size()}, file);
    check(name, [&] { formats::readFlash(file); });
    writeSeed(corpus, "flash", name, recipe);
  }
  const fs::path nanowire = real / "flash-2d-nanowire" / "nanowire_arrayhdf5_plt_cnt_0100";
  if (!fs::exists(nanowire)) return;
  // The real file's runtime parameter lists (their first entries) over the synthetic 2D tree.
  const hid_t file = H5Fopen(nanowire.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file < 0) return;
  RecipeWriter r;
  std::uint64_t count = 0;
  const std::string ints =
      realPairs(file, "integer runtime parameters", H5T_NATIVE_INT, 4, 24, count);
  r.dataset("integer runtime parameters", RecipeType::kPairFixedInt, {count}, ints,
            RecipeLayout::kContiguous, 80);
  const std::string reals = realPairs(file, "real scalars", H5T_NATIVE_DOUBLE, 8, 12, count);
  r.dataset("real scalars", RecipeType::kPairFixedDouble, {count}, reals, RecipeLayout::kContiguous,
            80);
  const formats::Hdf5Handle text(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(text.get(), 80);
  H5Tset_strpad(text.get(), H5T_STR_SPACEPAD);
  const std::string strings =
      realPairs(file, "string runtime parameters", text.get(), 80, 24, count);
  r.dataset("string runtime parameters", RecipeType::kPairFixedFixed, {count}, strings,
            RecipeLayout::kContiguous, 80);
  H5Fclose(file);
  writeSeed(corpus, "flash", "real_parameters_2d",
            flashRecipe({.dim = 2, .metadata = false}) + r.bytes());
}

// ---- Enzo ------------------------------------------------------------------------------------

struct EnzoGrid {
  glm::dvec3 left, right;
  glm::ivec3 dims;
};

// Root grid 2^3 over [0,1]^3 and one level-1 grid 2^3 over [0,0.5]^3, fields in sim.cpu0000.
std::vector<std::string> enzoParts(bool withHarrays) {
  const std::vector<EnzoGrid> grids{{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}},
                                    {{0, 0, 0}, {0.5, 0.5, 0.5}, {2, 2, 2}}};
  const std::string parameters =
      "InitialTime = 0.75\nTopGridRank = 3\nTopGridDimensions = 2 2 2\nRefineBy = 2\n"
      "DomainLeftEdge = 0 0 0\nDomainRightEdge = 1 1 1\nLeftFaceBoundaryCondition = 3 3 3\n"
      "RightFaceBoundaryCondition = 3 3 3\nComovingCoordinates = 0\nLengthUnits = 3e24\n";
  std::ostringstream hierarchy;
  RecipeWriter fields;
  const int next[] = {0, 0}, nextLevel[] = {2, 0};
  for (std::size_t n = 0; n < grids.size(); ++n) {
    const EnzoGrid& g = grids[n];
    hierarchy << "\nGrid = " << n + 1 << "\nGridRank = 3\nGridDimension = " << g.dims.x + 6 << ' '
              << g.dims.y + 6 << ' ' << g.dims.z + 6 << "\nGridStartIndex = 3 3 3\n"
              << "GridEndIndex = " << g.dims.x + 2 << ' ' << g.dims.y + 2 << ' ' << g.dims.z + 2
              << "\nGridLeftEdge = " << g.left.x << ' ' << g.left.y << ' ' << g.left.z
              << "\nGridRightEdge = " << g.right.x << ' ' << g.right.y << ' ' << g.right.z
              << "\nLevel = " << n << "\nBaryonFileName = /run/DD0001/sim.cpu0000\n"
              << "Pointer: Grid[" << n + 1 << "]->NextGridThisLevel = " << next[n] << "\n"
              << "Pointer: Grid[" << n + 1 << "]->NextGridNextLevel = " << nextLevel[n] << "\n";
    char group[16];
    std::snprintf(group, sizeof group, "Grid%08zu", n + 1);
    fields.group(group);
    for (const char* field : {"Density", "x-velocity"}) {
      std::vector<float> values;
      for (int i = 0; i < 8; ++i) values.push_back(float(n) + 0.5f * i);
      // Enzo writes big-endian float32: the root grid's are, the other grid's are not.
      std::string bytes = littleEndianBytes(values);
      if (n == 0)
        for (std::size_t at = 0; at < bytes.size(); at += 4)
          std::reverse(bytes.begin() + at, bytes.begin() + at + 4);
      fields.dataset(field, n == 0 ? RecipeType::kFloat32Be : RecipeType::kFloat32Le, {2, 2, 2},
                     bytes);
    }
    fields.dataset("particle_mass", RecipeType::kFloat64Le, {1}, std::string(8, '\0'));
    fields.end();
  }
  std::string harrays;
  if (withHarrays) {
    RecipeWriter table;
    table.dataset("Level", RecipeType::kInt32Le, {2}, littleEndianBytes(std::vector<int>{0, 1}));
    table.dataset("LeftEdges", RecipeType::kFloat64Le, {2, 3},
                  littleEndianBytes(std::vector<double>{0, 0, 0, 0, 0, 0}));
    table.dataset("RightEdges", RecipeType::kFloat64Le, {2, 3},
                  littleEndianBytes(std::vector<double>{1, 1, 1, 0.5, 0.5, 0.5}));
    table.dataset("ActiveDimensions", RecipeType::kInt32Le, {2, 3},
                  littleEndianBytes(std::vector<int>{2, 2, 2, 2, 2, 2}));
    harrays = table.bytes();
  }
  return {parameters, hierarchy.str(), fields.bytes(), "", harrays};
}

void enzoSeeds(const fs::path& corpus, const fs::path& scratch, const fs::path& real) {
  for (const bool withHarrays : {false, true}) {
    const auto parts = enzoParts(withHarrays);
    const fs::path dir = scratch / (withHarrays ? "enzo_table" : "enzo_text");
    writePart(dir, "sim", parts[0]);
    writePart(dir, "sim.hierarchy", parts[1]);
    writeRecipeFile({reinterpret_cast<const std::uint8_t*>(parts[2].data()), parts[2].size()},
                    dir / "sim.cpu0000");
    if (withHarrays)
      writeRecipeFile({reinterpret_cast<const std::uint8_t*>(parts[4].data()), parts[4].size()},
                      dir / "sim.harrays");
    check(dir.filename().string(), [&] { formats::readEnzo(dir / "sim.hierarchy"); });
    writeSeed(corpus, "enzo", withHarrays ? "two_grids_with_table" : "two_grids", joinParts(parts));
  }
  const fs::path dd = real / "enzo-moving7" / "DD0010";
  if (fs::exists(dd))
    writeSeed(corpus, "enzo", "real_parameters_and_hierarchy",
              joinParts({readFile(dd / "moving7_0010"), readFile(dd / "moving7_0010.hierarchy")}));
}

// ---- traces (.vtp) and seeds -----------------------------------------------------------------

void vtpSeeds(const fs::path& corpus, const fs::path& scratch) {
  flow::TraceSet traces;
  traces.vectorName = "v";
  traces.channelNames = {"p"};
  traces.seedIds = {0, 1};
  traces.directions = {1.0f, -1.0f};
  traces.steps = {2, 1};
  traces.reasons = {1, 2};
  traces.offsets = {0, 3, 5};
  for (int i = 0; i < 5; ++i) {
    traces.positions.push_back({0.25f * i, 1.0f - 0.5f * i, 2.0f});
    traces.times.push_back(i < 3 ? 0.5f * i : -0.5f * (i - 3));
    traces.vectors.push_back({1.0f, -0.5f * i, 0.0f});
    traces.channels.push_back(float(i));
  }
  for (const auto compression :
       {output::Compression::None, output::Compression::ZLib, output::Compression::LZ4}) {
    const fs::path file = scratch / "traces.vtp";
    output::VtpWriteOptions options;
    options.compression = compression;
    output::writeVtp(file, traces, options);
    writeSeed(corpus, "vtp",
              std::string("two_lines_") + std::string(output::compressionName(compression)),
              readFile(file));
  }
  writeSeed(corpus, "vtp", "ascii_hand_made",
            "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\" "
            "byte_order=\"LittleEndian\" header_type=\"UInt64\">\n<PolyData>\n"
            "<Piece NumberOfPoints=\"2\" NumberOfVerts=\"0\" NumberOfLines=\"1\" "
            "NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n<Points>\n"
            "<DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"ascii\">0 0 0 1 1 1"
            "</DataArray>\n</Points>\n<Lines>\n"
            "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">0 1</DataArray>\n"
            "<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">2</DataArray>\n"
            "</Lines>\n</Piece>\n</PolyData>\n</VTKFile>\n");
}

void seedFileSeeds(const fs::path& corpus, const fs::path& scratch) {
  flow::SeedList seeds;
  seeds.points = {{0.1, 0.2, 0.3}, {-1e-3, 5.0, 1e10}};
  output::writeSeedFile(scratch / "seeds.txt", seeds);
  writeSeed(corpus, "seeds", "written", readFile(scratch / "seeds.txt"));
  writeSeed(corpus, "seeds", "hand_made",
            "# rake\n0.5, 0.5, 0.5\n\t1\t2\t3  # tabs\n\n-0 +1e-3 2.5e+2\r\n");
}

}  // namespace
}  // namespace amrstream::fuzz

int main(int argc, char** argv) {
  using namespace amrstream::fuzz;
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s CORPUS_DIR [REAL_DATA_DIR]\n", argv[0]);
    return 2;
  }
  const fs::path corpus = argv[1];
  const fs::path real = argc > 2 ? fs::path(argv[2]) : fs::path();
  const fs::path scratch = fs::temp_directory_path() / "amrstream-make-corpus";
  fs::remove_all(scratch);
  fs::create_directories(scratch);
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  exaSeeds(corpus, scratch);
  gerrisSeeds(corpus, scratch, real);
  amrexSeeds(corpus, scratch, real);
  flashSeeds(corpus, scratch, real);
  enzoSeeds(corpus, scratch, real);
  vtpSeeds(corpus, scratch);
  seedFileSeeds(corpus, scratch);
  fs::remove_all(scratch);
  return 0;
}
