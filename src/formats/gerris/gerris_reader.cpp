#include "formats/gerris/gerris_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "amrstream/error.hpp"
#include "formats/cell_checks.hpp"
#include "formats/input_bytes.hpp"
#include "formats/text_numbers.hpp"

namespace amrstream::formats {
namespace {

constexpr int kMaxGerrisLevel = 30;
// A row holds a few numbers a column; no Gerris dump comes near this.
constexpr std::size_t kMostLineBytes = std::size_t(1) << 20;
constexpr double kLatticeTolerance = 0.01;  // of a cell size; the dump has 9 significant digits

struct Columns {
  std::vector<std::string> names;
  int x = -1, y = -1, z = -1, level = -1;
  std::optional<double> time;  // the header's last number
};

std::optional<double> parseNumber(std::string_view word) {
  if (!word.empty() && word.front() == '+') word.remove_prefix(1);
  double value = 0.0;
  auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
  if (error != std::errc() || end != word.data() + word.size()) return std::nullopt;
  return value;
}

Columns parseHeader(const std::string& line, const std::string& where) {
  if (line.empty() || line[0] != '#')
    throw InputError(where, "the first line is not a Gerris header '# 1:x 2:y 3:z ... N:Lev'");
  Columns columns;
  const std::vector<std::string_view> words = splitWords(std::string_view(line).substr(1));
  for (std::size_t w = 0; w < words.size(); ++w) {
    const std::string_view word = words[w];
    const std::size_t colon = word.find(':');
    if (colon == std::string_view::npos && w + 1 == words.size() && parseNumber(word)) {
      if (std::isfinite(*parseNumber(word))) columns.time = parseNumber(word);  // the header's end
      break;
    }
    if (colon == std::string_view::npos)
      throw InputError(where,
                       fmt::format("garbled header column '{}' (expected N:NAME)", excerpt(word)));
    int number = 0;
    auto [end, error] = std::from_chars(word.data(), word.data() + colon, number);
    const std::string name(word.substr(colon + 1));
    if (error != std::errc() || end != word.data() + colon || name.empty())
      throw InputError(where,
                       fmt::format("garbled header column '{}' (expected N:NAME)", excerpt(word)));
    if (number != static_cast<int>(columns.names.size()) + 1)
      throw InputError(where, fmt::format("header column '{}' should be number {}", excerpt(word),
                                          columns.names.size() + 1));
    if (std::find(columns.names.begin(), columns.names.end(), name) != columns.names.end())
      throw InputError(where, fmt::format("header names column '{}' twice", excerpt(name)));
    const int index = static_cast<int>(columns.names.size());
    if (name == "x") columns.x = index;
    if (name == "y") columns.y = index;
    if (name == "z") columns.z = index;
    if (name == "Lev") columns.level = index;
    columns.names.push_back(name);
  }
  for (auto [index, name] :
       {std::pair{columns.x, "x"}, {columns.y, "y"}, {columns.z, "z"}, {columns.level, "Lev"}})
    if (index < 0)
      throw InputError(where, fmt::format("the header has no '{}' column (a 3D Gerris dump "
                                          "needs x, y, z and Lev)",
                                          name));
  if (columns.names.size() == 4)
    throw InputError(where, "the header names no value columns besides x, y, z and Lev");
  return columns;
}

// Opens `file` on `in` and parses its first line, leaving `in` at the first row. `consumed`
// counts the bytes read, line breaks included.
Columns readHeader(std::ifstream& in, const std::filesystem::path& file, std::uint64_t& size,
                   std::uint64_t& consumed) {
  const std::string source = file.string();
  size = openRegularFile(in, file, "the Gerris file");
  refuseHoles(file, size, "the Gerris file");
  std::string line;
  if (!readBoundedLine(in, line, kMostLineBytes, source, 1))
    throw InputError(source, "the file is empty (no Gerris header)");
  consumed = line.size() + 1;
  return parseHeader(line, source + ":1");
}

struct Leaf {
  glm::dvec3 centre;
  int level;
  int line;
};

// The value columns: every column but x, y, z and Lev, each a channel without values yet.
struct ValueColumns {
  std::vector<Channel> channels;
  std::vector<int> columns;  // the column of each channel
};

ValueColumns valueColumns(const Columns& columns) {
  ValueColumns values;
  for (int c = 0; c < static_cast<int>(columns.names.size()); ++c) {
    if (c == columns.x || c == columns.y || c == columns.z || c == columns.level) continue;
    values.channels.push_back({columns.names[c], {}});
    values.columns.push_back(c);
  }
  return values;
}

// The rows after the header, from `in`: their leaves, and their values appended to the channels.
// `consumed` counts on from the header's bytes; `fileSize` is the file's size when opened.
std::vector<Leaf> readLeaves(std::ifstream& in, const std::string& source, const Columns& columns,
                             ValueColumns& values, std::uint64_t fileSize,
                             std::uint64_t& consumed) {
  std::vector<Channel>& channels = values.channels;
  const std::vector<int>& channelColumns = values.columns;
  std::string line;
  std::vector<Leaf> leaves;
  std::vector<double> row(columns.names.size());
  for (int number = 2; readBoundedLine(in, line, kMostLineBytes, source, number); ++number) {
    consumed += line.size() + 1;
    const std::vector<std::string_view> words = splitWords(line);
    if (words.empty()) continue;
    const std::string where = fmt::format("{}:{}", source, number);
    if (words.size() != row.size())
      throw InputError(
          where, fmt::format("{} columns, but the header names {}", words.size(), row.size()));
    for (std::size_t c = 0; c < words.size(); ++c) {
      const std::optional<double> value = parseNumber(words[c]);
      if (!value)
        throw InputError(where, fmt::format("column '{}' is not a number: '{}'",
                                            excerpt(columns.names[c]), excerpt(words[c])));
      row[c] = *value;
    }
    const double level = row[columns.level];
    if (!(level >= 0 && level <= kMaxGerrisLevel) || level != std::floor(level))
      throw InputError(
          where, fmt::format("level {} is not an integer in [0, {}]", level, kMaxGerrisLevel));
    Leaf leaf{{row[columns.x], row[columns.y], row[columns.z]}, static_cast<int>(level), number};
    const double size = std::ldexp(1.0, -leaf.level);
    for (int axis = 0; axis < 3; ++axis) {
      const double k = (leaf.centre[axis] + 0.5) / size - 0.5;
      if (!std::isfinite(k) || std::abs(k - std::round(k)) > kLatticeTolerance)
        throw InputError(where, fmt::format("the centre {} = {} is not on the level-{} lattice "
                                            "(k + 1/2) * {} - 1/2",
                                            "xyz"[axis], leaf.centre[axis], leaf.level, size));
    }
    leaves.push_back(leaf);
    for (std::size_t c = 0; c < channels.size(); ++c) {
      const double value = row[channelColumns[c]];
      if (const auto problem = unusableFieldValue(value))
        throw InputError(where, fmt::format("column '{}' is {}: '{}'", excerpt(channels[c].name),
                                            *problem, excerpt(words[channelColumns[c]])));
      channels[c].values.push_back(static_cast<float>(value));
    }
  }
  // `consumed` counts a line break after the last line too, which the file may lack.
  if (in.bad() || consumed < fileSize)
    throw InputError(source, fmt::format("read {} of its {} bytes; the file is shorter than it "
                                         "was a moment ago (changed while being read?)",
                                         std::min(consumed, fileSize), fileSize));
  return leaves;
}

// The finest lattice of the leaves: its level, its cell size and the domain corner on it.
struct Lattice {
  int finest = 0;
  double finestSize = 1.0;
  glm::dvec3 origin{0.0};
};

Lattice finestLattice(const std::vector<Leaf>& leaves, const std::string& source) {
  int finest = 0, coarsest = kMaxGerrisLevel;
  glm::dvec3 lowest(std::numeric_limits<double>::max());
  for (const Leaf& leaf : leaves) {
    finest = std::max(finest, leaf.level);
    coarsest = std::min(coarsest, leaf.level);
    lowest = glm::min(lowest, leaf.centre - 0.5 * std::ldexp(1.0, -leaf.level));
  }
  if (finest - coarsest > bricks::kMaxLevel)
    throw InputError(source, fmt::format("levels {}..{} span more than {} refinements", coarsest,
                                         finest, bricks::kMaxLevel));
  const double finestSize = std::ldexp(1.0, -finest);
  // Snap the domain corner onto the finest lattice -1/2 + k * finestSize.
  const glm::dvec3 origin = glm::round((lowest + 0.5) / finestSize) * finestSize - 0.5;
  return {finest, finestSize, origin};
}

// The leaves' lower corners and levels in finest cells from the lattice's origin.
void placeLeaves(const std::vector<Leaf>& leaves, const Lattice& lattice, const std::string& source,
                 std::vector<glm::ivec3>& lowers, std::vector<std::uint8_t>& levels) {
  lowers.reserve(leaves.size());
  levels.reserve(leaves.size());
  const double maxExtent = std::ldexp(1.0, bricks::kMaxExtentBits);
  for (const Leaf& leaf : leaves) {
    const glm::dvec3 corner = glm::round(
        (leaf.centre - 0.5 * std::ldexp(1.0, -leaf.level) - lattice.origin) / lattice.finestSize);
    if (glm::any(glm::greaterThanEqual(corner, glm::dvec3(maxExtent))))
      throw InputError(fmt::format("{}:{}", source, leaf.line),
                       fmt::format("the cell lies more than 2^{} finest cells from the domain "
                                   "corner",
                                   bricks::kMaxExtentBits));
    lowers.emplace_back(corner);
    levels.push_back(static_cast<std::uint8_t>(lattice.finest - leaf.level));
  }
}

}  // namespace

bricks::AmrField readGerris(const std::filesystem::path& file) {
  const std::string source = file.string();
  std::ifstream in;
  std::uint64_t size = 0, consumed = 0;
  const Columns columns = readHeader(in, file, size, consumed);

  ValueColumns values = valueColumns(columns);
  const std::vector<Leaf> leaves = readLeaves(in, source, columns, values, size, consumed);
  if (leaves.empty()) throw InputError(source, "the file has a header but no cells");
  const Lattice lattice = finestLattice(leaves, source);

  std::vector<glm::ivec3> lowers;
  std::vector<std::uint8_t> levels;
  placeLeaves(leaves, lattice, source, lowers, levels);
  const WorldTransform transform{lattice.origin, glm::dvec3(lattice.finestSize)};
  if (const auto problem = unrepresentablePositions(transform, lowers, levels))
    throw InputError(source, "the cells cannot be placed: " + *problem);
  bricks::AmrField field(std::move(lowers), std::move(levels), std::move(values.channels),
                         transform, source);
  DatasetInfo info;
  info.format = "Gerris";
  info.time = columns.time;
  info.finestFileLevel = lattice.finest;
  info.levelsCountDown = true;
  info.levelName = "Gerris level (cell size 2^-level of the root box)";
  field.setInfo(std::move(info));
  return field;
}

std::optional<double> readGerrisTime(const std::filesystem::path& file) {
  std::ifstream in;
  std::uint64_t size = 0, consumed = 0;
  return readHeader(in, file, size, consumed).time;
}

}  // namespace amrstream::formats
