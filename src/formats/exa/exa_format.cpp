#include "formats/exa/exa_format.hpp"

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <span>
#include <sstream>

#include "amrstream/error.hpp"
#include "formats/cell_checks.hpp"
#include "formats/file_set_writer.hpp"
#include "formats/input_bytes.hpp"
#include "formats/piece_reads.hpp"
#include "formats/text_numbers.hpp"
#include "util/first_failing.hpp"
#include "util/huge_pages.hpp"

namespace amrstream::formats {

static_assert(std::endian::native == std::endian::little,
              "the ExaBricks readers assume a little-endian host");

namespace {

constexpr std::size_t kCellBytes = 4 * sizeof(std::int32_t);
constexpr std::uint64_t kMaxCells = std::uint64_t{1} << 31;

struct ExaConfig {
  std::filesystem::path cells;
  std::vector<std::pair<std::string, std::filesystem::path>> scalars;
  WorldTransform transform;
  int originLine = 0, spacingLine = 0;  // 0: not in the file, the default
  DatasetInfo info;
};

constexpr const char* kDirectives =
    "cells, scalar, bricks, origin, spacing, time, periodic, "
    "length-unit, time-unit or unit";

glm::dvec3 readVector(std::istringstream& words, const std::string& where,
                      const std::string& what) {
  glm::dvec3 v;
  for (int a = 0; a < 3; ++a) {
    std::string word;
    if (!(words >> word)) throw InputError(where, fmt::format("'{}' needs three numbers", what));
    v[a] = parseFinite(word, where, fmt::format("'{}' {}", what, "xyz"[a]));
  }
  return v;
}

double readTime(std::istringstream& words, const std::string& where) {
  std::string word;
  words >> word;
  double time = 0.0;
  const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), time);
  if (word.empty() || error != std::errc() || end != word.data() + word.size() ||
      !std::isfinite(time))
    throw InputError(where, fmt::format("'time' needs one finite number, got '{}'", excerpt(word)));
  return time;
}

std::array<bool, 3> readPeriodic(std::istringstream& words, const std::string& where) {
  std::vector<std::string> flags;
  for (std::string word; words >> word;) flags.push_back(word);
  std::array<bool, 3> periodic{};
  const bool valid = flags.size() == 3 && std::ranges::all_of(flags, [](const std::string& f) {
                       return f == "0" || f == "1";
                     });
  if (!valid)
    throw InputError(where, fmt::format("'periodic' needs three flags 0 or 1 (x y z), got {} "
                                        "value{}",
                                        flags.size(), flags.size() == 1 ? "" : "s"));
  for (int a = 0; a < 3; ++a) periodic[a] = flags[a] == "1";
  return periodic;
}

// The rest of the line, trimmed: unit names may hold spaces.
std::string readText(std::istringstream& words, const std::string& where,
                     const std::string& keyword) {
  std::string text;
  std::getline(words, text);
  text.erase(0, text.find_first_not_of(" \t\r"));
  text.erase(text.find_last_not_of(" \t\r") + 1);
  if (text.empty()) throw InputError(where, fmt::format("'{}' needs a text", keyword));
  return text;
}

ExaConfig parseConfig(const std::filesystem::path& config) {
  const std::string text = readWholeFile(config, "the config file");
  std::istringstream in(text);
  const std::filesystem::path dir = config.parent_path();
  ExaConfig result;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (auto hash = line.find('#'); hash != std::string::npos) line.resize(hash);
    std::istringstream words(line);
    std::string keyword;
    if (!(words >> keyword)) continue;
    const std::string where = fmt::format("{}:{}", config.string(), number);
    if (line.find('\0') != std::string::npos)
      throw InputError(where, "the line holds a NUL byte: not a text config");
    std::string name, file;
    if (keyword == "cells") {
      if (!(words >> file)) throw InputError(where, "'cells' needs a file name");
      result.cells = dir / file;
    } else if (keyword == "scalar") {
      if (!(words >> name >> file)) throw InputError(where, "'scalar' needs a name and a file");
      result.scalars.emplace_back(name, dir / file);
    } else if (keyword == "bricks") {
      // A prebuilt ExaBricks brick file: we build bricks from the cells instead.
      if (!(words >> file)) throw InputError(where, "'bricks' needs a file name");
    } else if (keyword == "origin") {
      result.transform.origin = readVector(words, where, keyword);
      result.originLine = number;
    } else if (keyword == "spacing") {
      const glm::dvec3 spacing = readVector(words, where, keyword);
      for (int a = 0; a < 3; ++a)
        if (!(spacing[a] > 0) || !std::isnormal(spacing[a]))
          throw InputError(where, fmt::format("'spacing' must be positive and not subnormal, got "
                                              "{} along {}",
                                              spacing[a], "xyz"[a]));
      result.transform.spacing = spacing;
      result.spacingLine = number;
    } else if (keyword == "time") {
      result.info.time = readTime(words, where);
    } else if (keyword == "periodic") {
      result.info.periodic = readPeriodic(words, where);
      result.info.periodicKnown = true;
    } else if (keyword == "length-unit") {
      result.info.lengthUnit = readText(words, where, keyword);
    } else if (keyword == "time-unit") {
      result.info.timeUnit = readText(words, where, keyword);
    } else if (keyword == "unit") {
      std::string channel;
      if (!(words >> channel)) throw InputError(where, "'unit' needs a channel's name and a unit");
      result.info.units[channel] = readText(words, where, keyword);
    } else {
      throw InputError(where, fmt::format("unknown directive '{}' (expected {})", excerpt(keyword),
                                          kDirectives));
    }
    if (words >> name)
      throw InputError(where, fmt::format("unexpected '{}' after '{}'", excerpt(name), keyword));
  }
  if (result.cells.empty())
    throw InputError(config.string(), "no 'cells FILE' line: amrstream needs the cells file");
  return result;
}

// The cells file: int32 x, y, z, level per cell, checked before they become a field; read in
// pieces on all cores, so that the records never sit in memory beside the whole field. Returns
// their bounding box.
CellsBounds readCells(const std::filesystem::path& path, std::vector<glm::ivec3>& lowers,
                      std::vector<std::uint8_t>& levels) {
  std::ifstream in;
  const std::uint64_t size = openRegularFile(in, path, "the cells file");
  if (size % kCellBytes != 0)
    throw InputError(path.string(),
                     fmt::format("size {} bytes is not a multiple of {} (int32 x, y, z, level per "
                                 "cell); the file is truncated or not a .cells file",
                                 size, kCellBytes));
  const std::uint64_t n = size / kCellBytes;
  if (n > kMaxCells)
    throw InputError(path.string(),
                     fmt::format("holds {} cells, more than the {} accepted", n, kMaxCells));
  refuseHoles(path, size, "the cells file");
  resizeInHugePages(lowers, n);
  resizeInHugePages(levels, n);
  constexpr std::size_t kPiece = std::size_t(1) << 18;  // cells
  // The first cell with a level out of range is named, whichever piece comes first.
  std::atomic<std::size_t> firstBad{n};
  forEachPiece(path, 0, size, kPiece * kCellBytes, "the cells file",
               [&](std::uint64_t offset, std::span<const char> bytes) {
                 const std::size_t first = offset / kCellBytes;
                 const std::size_t count = bytes.size() / kCellBytes;
                 for (std::size_t k = 0; k < count; ++k) {
                   std::int32_t cell[4];
                   std::memcpy(cell, bytes.data() + k * kCellBytes, kCellBytes);
                   lowers[first + k] = glm::ivec3(cell[0], cell[1], cell[2]);
                   levels[first + k] = static_cast<std::uint8_t>(cell[3]);
                   if (cell[3] < 0 || cell[3] > bricks::kMaxLevel) {
                     std::size_t seen = firstBad.load();
                     while (first + k < seen && !firstBad.compare_exchange_weak(seen, first + k)) {
                     }
                     break;
                   }
                 }
               });
  if (const std::size_t bad = firstBad.load(); bad < n) {
    std::int32_t cell[4];
    readExactly(in.seekg(std::streamoff(bad * kCellBytes)), path, bad * kCellBytes,
                reinterpret_cast<char*>(cell), kCellBytes, "the cells file");
    throw InputError(path.string(), fmt::format("cell {} has level {}; levels must be in 0..{}",
                                                bad, cell[3], bricks::kMaxLevel));
  }
  return requireCellsWithinExtent(lowers, levels, path.string());
}

// Opens a scalars file and checks that it holds one float32 for each of `cells` cells.
std::uint64_t openScalars(std::ifstream& in, const std::filesystem::path& path, std::size_t cells,
                          const std::filesystem::path& cellsPath) {
  const std::uint64_t size = openRegularFile(in, path, "the scalars file");
  if (size != cells * sizeof(float))
    throw InputError(path.string(),
                     fmt::format("holds {} bytes ({} float32 values) but {} has {} cells", size,
                                 double(size) / sizeof(float), cellsPath.string(), cells));
  return size;
}

// One float32 per cell; the size is checked before anything is allocated. Errors give the
// cell's lower corner when `lowers` holds the cells.
void readScalarsInto(const std::string& name, const std::filesystem::path& path,
                     const std::filesystem::path& cellsPath, std::size_t cells,
                     std::span<const glm::ivec3> lowers, std::span<float> values) {
  std::ifstream in;
  const std::uint64_t size = openScalars(in, path, cells, cellsPath);
  in.close();
  if (values.size() != cells)
    throw InputError(path.string(), fmt::format("{} values asked for of a channel of {} cells",
                                                values.size(), cells));
  readInPieces(path, 0, reinterpret_cast<char*>(values.data()), size, "the scalars file");
  // A float is unusable exactly when it is not finite: NaN fails the comparison.
  const std::size_t i = firstFailing(
      cells, [&](std::size_t k) { return !(std::abs(values[k]) <= kLargestFieldValue); });
  if (i < cells) {
    const std::string problem = *unusableFieldValue(values[i]);
    throw InputError(path.string(),
                     lowers.empty()
                         ? fmt::format("channel '{}': the value of cell {} is {}", name, i, problem)
                         : fmt::format("channel '{}': the value of cell {} (lower corner {}, {}, "
                                       "{}) is {}",
                                       name, i, lowers[i].x, lowers[i].y, lowers[i].z, problem));
  }
}

std::vector<float> readScalars(const std::string& name, const std::filesystem::path& path,
                               const std::filesystem::path& cellsPath, std::size_t cells,
                               std::span<const glm::ivec3> lowers) {
  std::vector<float> values;
  resizeInHugePages(values, cells);
  readScalarsInto(name, path, cellsPath, cells, lowers, values);
  return values;
}

std::string lineOf(int line) {
  return line == 0 ? std::string("the default") : fmt::format("line {}", line);
}

}  // namespace

ExaCells readExaCells(const std::filesystem::path& config) {
  const ExaConfig exa = parseConfig(config);
  std::vector<glm::ivec3> lowers;
  std::vector<std::uint8_t> levels;
  const CellsBounds bounds = readCells(exa.cells, lowers, levels);
  if (lowers.empty()) throw InputError(exa.cells.string(), "the cells file holds no cells");
  if (const auto problem = unrepresentablePositions(exa.transform, bounds))
    throw InputError(config.string(),
                     fmt::format("origin ({}) and spacing ({}) cannot place the cells: {}",
                                 lineOf(exa.originLine), lineOf(exa.spacingLine), *problem));

  std::vector<ExaChannelFile> files;
  for (const auto& [name, path] : exa.scalars) {
    for (const ExaChannelFile& earlier : files)
      if (earlier.name == name)
        throw InputError(config.string(), fmt::format("the channel '{}' is named twice", name));
    files.push_back({name, path, exa.cells, lowers.size()});
    std::ifstream in;
    openScalars(in, path, lowers.size(), exa.cells);  // a missing or short file fails first
  }
  bricks::AmrField field(std::move(lowers), std::move(levels), {}, exa.transform, config.string());
  DatasetInfo info = exa.info;
  info.format = "ExaBricks";
  info.finestFileLevel = 0;
  info.levelsCountDown = false;
  info.levelName = "ExaBricks level (0 = finest)";
  field.setInfo(std::move(info));
  return {std::move(field), std::move(files)};
}

std::vector<float> readExaChannel(const ExaChannelFile& channel) {
  return readScalars(channel.name, channel.path, channel.cellsPath, channel.cellCount, {});
}

void readExaChannelInto(const ExaChannelFile& channel, std::span<float> into) {
  readScalarsInto(channel.name, channel.path, channel.cellsPath, channel.cellCount, {}, into);
}

bricks::AmrField readExa(const std::filesystem::path& config) {
  ExaCells exa = readExaCells(config);
  for (const ExaChannelFile& file : exa.channels)
    exa.field.addChannel({file.name, readScalars(file.name, file.path, file.cellsPath,
                                                 exa.field.cellCount(), exa.field.lowers())});
  return std::move(exa.field);
}

std::optional<double> readExaTime(const std::filesystem::path& config) {
  return parseConfig(config).info.time;
}

namespace {

std::span<const std::byte> bytesOf(const void* data, std::size_t size) {
  return {static_cast<const std::byte*>(data), size};
}

// A name the .exa's whitespace-separated lines and a file name can hold.
void requireWritableName(const std::string& name, const std::string& what,
                         const std::filesystem::path& exaPath) {
  if (name.empty() || name.find_first_of(" \t\r\n#/") != std::string::npos)
    throw InputError(exaPath.string(),
                     fmt::format("the {} '{}' is empty or holds a blank, '#' or '/', which a .exa "
                                 "line or file name cannot hold",
                                 what, name));
}

// The `time`, `time-unit`, `length-unit` and `periodic` lines for what the field's info knows.
std::string infoLines(const DatasetInfo& info, const std::filesystem::path& exaPath) {
  std::string lines;
  if (info.time) lines += fmt::format("time {:.17g}\n", *info.time);
  for (const auto& [keyword, text] :
       {std::pair{"time-unit", &info.timeUnit}, {"length-unit", &info.lengthUnit}}) {
    if (text->empty()) continue;
    if (text->find_first_of("#\r\n") != std::string::npos)
      throw InputError(exaPath.string(),
                       fmt::format("the {} '{}' holds '#' or a line break, which a .exa line "
                                   "cannot hold",
                                   keyword, *text));
    lines += fmt::format("{} {}\n", keyword, *text);
  }
  for (const auto& [channel, unit] : info.units) {
    requireWritableName(channel, "channel", exaPath);
    if (unit.find_first_of("#\r\n") != std::string::npos || unit.empty())
      throw InputError(exaPath.string(),
                       fmt::format("the unit '{}' of {} is empty or holds '#' or a line break, "
                                   "which a .exa line cannot hold",
                                   unit, channel));
    lines += fmt::format("unit {} {}\n", channel, unit);
  }
  if (info.periodicKnown)
    lines += fmt::format("periodic {:d} {:d} {:d}\n", info.periodic[0], info.periodic[1],
                         info.periodic[2]);
  return lines;
}

}  // namespace

std::filesystem::path writeExa(const bricks::AmrField& field, const std::filesystem::path& prefix) {
  const std::string base = prefix.filename().string();
  const std::filesystem::path dir = prefix.parent_path();
  const auto file = [&](const std::string& suffix) { return base + suffix; };
  const std::filesystem::path exaPath = dir / file(".exa");
  // Everything a line must hold is checked before any file is written.
  const std::string info = infoLines(field.info(), exaPath);
  requireWritableName(base, "file name prefix", exaPath);
  for (const Channel& channel : field.channels())
    requireWritableName(channel.name, "channel name", exaPath);

  std::vector<std::int32_t> cells(4 * field.cellCount());
  for (std::size_t i = 0; i < field.cellCount(); ++i) {
    const glm::ivec3 lower = field.lowers()[i];
    cells[4 * i + 0] = lower.x;
    cells[4 * i + 1] = lower.y;
    cells[4 * i + 2] = lower.z;
    cells[4 * i + 3] = field.levels()[i];
  }
  FileSetWriter files;
  files.add(dir / file(".cells"), bytesOf(cells.data(), cells.size() * sizeof(std::int32_t)));

  std::ostringstream config;
  config << "# amrstream ExaBricks export of " << field.source() << "\n";
  config << "cells " << file(".cells") << "\n";
  for (const Channel& channel : field.channels()) {
    const std::string name = file("." + channel.name + ".scalars");
    files.add(dir / name, bytesOf(channel.values.data(), channel.values.size() * sizeof(float)));
    config << "scalar " << channel.name << " " << name << "\n";
  }
  const WorldTransform& t = field.transform();
  config << fmt::format("origin {:.17g} {:.17g} {:.17g}\n", t.origin.x, t.origin.y, t.origin.z);
  config << fmt::format("spacing {:.17g} {:.17g} {:.17g}\n", t.spacing.x, t.spacing.y, t.spacing.z);
  config << info;
  const std::string text = config.str();
  files.add(exaPath, bytesOf(text.data(), text.size()));  // last: it names the others
  files.commit();
  return exaPath;
}

}  // namespace amrstream::formats
