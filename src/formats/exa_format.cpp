#include "exa_format.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

#include "util/input_error.hpp"

namespace amrstream::formats {

static_assert(std::endian::native == std::endian::little,
              "the ExaBricks readers assume a little-endian host");

namespace {

std::vector<char> readWholeFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) throw InputError(path.string(), "cannot open the file");
  const std::streamsize size = in.tellg();
  std::vector<char> bytes(static_cast<std::size_t>(size));
  in.seekg(0);
  if (!in.read(bytes.data(), size)) throw InputError(path.string(), "cannot read the file");
  return bytes;
}

struct ExaConfig {
  std::filesystem::path cells;
  std::vector<std::pair<std::string, std::filesystem::path>> scalars;
  bricks::WorldTransform transform;
  bricks::DatasetInfo info;
};

constexpr const char* kDirectives = "cells, scalar, bricks, origin, spacing, time, periodic, "
                                    "length-unit or time-unit";

glm::dvec3 readVector(std::istringstream& words, const std::string& where,
                      const std::string& what) {
  glm::dvec3 v;
  if (!(words >> v.x >> v.y >> v.z))
    throw InputError(where, fmt::format("'{}' needs three numbers", what));
  return v;
}

double readTime(std::istringstream& words, const std::string& where) {
  std::string word;
  words >> word;
  double time = 0.0;
  const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), time);
  if (word.empty() || error != std::errc() || end != word.data() + word.size() ||
      !std::isfinite(time))
    throw InputError(where, fmt::format("'time' needs one finite number, got '{}'", word));
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
  std::ifstream in(config);
  if (!in) throw InputError(config.string(), "cannot open the config file");
  const std::filesystem::path dir = config.parent_path();
  ExaConfig result;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (auto hash = line.find('#'); hash != std::string::npos) line.resize(hash);
    std::istringstream words(line);
    std::string keyword;
    if (!(words >> keyword)) continue;
    const std::string where = fmt::format("{}:{}", config.string(), number);
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
    } else if (keyword == "spacing") {
      result.transform.spacing = readVector(words, where, keyword);
      if (glm::any(glm::lessThanEqual(result.transform.spacing, glm::dvec3(0.0))))
        throw InputError(where, "'spacing' must be positive");
    } else if (keyword == "time") {
      result.info.time = readTime(words, where);
    } else if (keyword == "periodic") {
      result.info.periodic = readPeriodic(words, where);
      result.info.periodicKnown = true;
    } else if (keyword == "length-unit") {
      result.info.lengthUnit = readText(words, where, keyword);
    } else if (keyword == "time-unit") {
      result.info.timeUnit = readText(words, where, keyword);
    } else {
      throw InputError(where,
                       fmt::format("unknown directive '{}' (expected {})", keyword, kDirectives));
    }
    if (words >> name)
      throw InputError(where, fmt::format("unexpected '{}' after '{}'", name, keyword));
  }
  if (result.cells.empty())
    throw InputError(config.string(), "no 'cells FILE' line: amrstream needs the cells file");
  return result;
}

}  // namespace

bricks::AmrField readExa(const std::filesystem::path& config) {
  const ExaConfig exa = parseConfig(config);

  constexpr std::size_t kCellBytes = 4 * sizeof(std::int32_t);
  const std::vector<char> cellBytes = readWholeFile(exa.cells);
  if (cellBytes.size() % kCellBytes != 0)
    throw InputError(exa.cells.string(),
                     fmt::format("size {} bytes is not a multiple of {} (int32 x, y, z, level per "
                                 "cell); the file is truncated or not a .cells file",
                                 cellBytes.size(), kCellBytes));
  const std::size_t n = cellBytes.size() / kCellBytes;
  std::vector<glm::ivec3> lowers(n);
  std::vector<std::uint8_t> levels(n);
  for (std::size_t i = 0; i < n; ++i) {
    std::int32_t cell[4];
    std::memcpy(cell, cellBytes.data() + i * kCellBytes, kCellBytes);
    if (cell[3] < 0 || cell[3] > bricks::kMaxLevel)
      throw InputError(exa.cells.string(), fmt::format("cell {} has level {}; levels must be in "
                                                       "0..{}",
                                                       i, cell[3], bricks::kMaxLevel));
    lowers[i] = glm::ivec3(cell[0], cell[1], cell[2]);
    levels[i] = static_cast<std::uint8_t>(cell[3]);
  }

  std::vector<bricks::Channel> channels;
  for (const auto& [name, path] : exa.scalars) {
    const std::vector<char> bytes = readWholeFile(path);
    if (bytes.size() != n * sizeof(float))
      throw InputError(
          path.string(),
          fmt::format("holds {} bytes ({} float32 values) but {} has {} cells", bytes.size(),
                      double(bytes.size()) / sizeof(float), exa.cells.string(), n));
    bricks::Channel channel{name, std::vector<float>(n)};
    std::memcpy(channel.values.data(), bytes.data(), bytes.size());
    channels.push_back(std::move(channel));
  }
  bricks::AmrField field(std::move(lowers), std::move(levels), std::move(channels), exa.transform,
                         config.string());
  bricks::DatasetInfo info = exa.info;
  info.format = "ExaBricks";
  info.finestFileLevel = 0;
  info.levelsCountDown = false;
  info.levelName = "ExaBricks level (0 = finest)";
  field.setInfo(std::move(info));
  return field;
}

std::optional<double> readExaTime(const std::filesystem::path& config) {
  return parseConfig(config).info.time;
}

namespace {

void writeBytes(const std::filesystem::path& path, const void* data, std::size_t size) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw InputError(path.string(), "cannot create the file");
  out.write(static_cast<const char*>(data), static_cast<std::streamsize>(size));
  if (!out.flush()) throw InputError(path.string(), "write failed (disk full?)");
}

// The `time`, `time-unit`, `length-unit` and `periodic` lines for what the field's info knows.
std::string infoLines(const bricks::DatasetInfo& info, const std::filesystem::path& exaPath) {
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
  const std::string info = infoLines(field.info(), exaPath);  // checked before writing anything

  std::vector<std::int32_t> cells(4 * field.cellCount());
  for (std::size_t i = 0; i < field.cellCount(); ++i) {
    const glm::ivec3 lower = field.lowers()[i];
    cells[4 * i + 0] = lower.x;
    cells[4 * i + 1] = lower.y;
    cells[4 * i + 2] = lower.z;
    cells[4 * i + 3] = field.levels()[i];
  }
  writeBytes(dir / file(".cells"), cells.data(), cells.size() * sizeof(std::int32_t));

  std::ostringstream config;
  config << "# amrstream ExaBricks export of " << field.source() << "\n";
  config << "cells " << file(".cells") << "\n";
  for (const bricks::Channel& channel : field.channels()) {
    const std::string name = file("." + channel.name + ".scalars");
    writeBytes(dir / name, channel.values.data(), channel.values.size() * sizeof(float));
    config << "scalar " << channel.name << " " << name << "\n";
  }
  const bricks::WorldTransform& t = field.transform();
  config << fmt::format("origin {:.17g} {:.17g} {:.17g}\n", t.origin.x, t.origin.y, t.origin.z);
  config << fmt::format("spacing {:.17g} {:.17g} {:.17g}\n", t.spacing.x, t.spacing.y, t.spacing.z);
  config << info;
  const std::string text = config.str();
  writeBytes(exaPath, text.data(), text.size());
  return exaPath;
}

}  // namespace amrstream::formats
