// ExaBricks files: a written dataset reads back identically, with its time, units and periodic
// axes; truncated, inconsistent and malformed files are rejected with errors naming the file (and
// line) and the numbers involved.

#include "formats/exa/exa_format.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <vector>

#include "amrstream/error.hpp"
#include "formats/load_input.hpp"
#include "input_error_of.hpp"
#include "random_amr.hpp"
#include "special_files.hpp"
#include "temp_dir_test.hpp"

namespace amrstream::formats {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
namespace fs = std::filesystem;

class ExaFormat : public testing::TempDirTest {
 protected:
  fs::path writeSample() {
    bricks::AmrField field = testing::randomAmr(7);
    return writeExa(field, dir_ / "sample");
  }
  static void writeText(const fs::path& path, const std::string& text) {
    std::ofstream(path) << text;
  }
  static std::string errorOf(const fs::path& config) {
    return testing::inputErrorOf([&] { readExa(config); });
  }
  // A config naming `cells` (x, y, z, level per cell) written beside it, and one scalar channel.
  fs::path writeCells(const std::vector<std::array<std::int32_t, 4>>& cells,
                      const std::string& transformLines = "") {
    std::ofstream(dir_ / "raw.cells", std::ios::binary)
        .write(reinterpret_cast<const char*>(cells.data()),
               std::streamsize(cells.size() * sizeof(cells[0])));
    const std::vector<float> values(cells.size(), 1.0f);
    std::ofstream(dir_ / "raw.v.scalars", std::ios::binary)
        .write(reinterpret_cast<const char*>(values.data()),
               std::streamsize(values.size() * sizeof(float)));
    writeText(dir_ / "raw.exa", "cells raw.cells\nscalar v raw.v.scalars\n" + transformLines);
    return dir_ / "raw.exa";
  }
  // Writes `value` as the float32 of cell `cell` in `scalars`.
  static void poke(const fs::path& scalars, std::size_t cell, float value) {
    std::fstream f(scalars, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(std::streamoff(cell * sizeof(float)));
    f.write(reinterpret_cast<const char*>(&value), sizeof value);
  }
};

TEST_F(ExaFormat, RoundTripsCellsChannelsAndTransform) {
  testing::RandomAmrOptions options;
  options.origin = glm::ivec3(-8, 0, 16);
  const bricks::AmrField random = testing::randomAmr(3, options);
  const bricks::AmrField original({random.lowers().begin(), random.lowers().end()},
                                  {random.levels().begin(), random.levels().end()},
                                  random.channels(), {{0.5, -1.0, 1e6}, {0.125, 0.25, 3.0}},
                                  "original");
  const fs::path config = writeExa(original, dir_ / "roundtrip");
  EXPECT_EQ(config, dir_ / "roundtrip.exa");

  const bricks::AmrField read = readExa(config);
  ASSERT_EQ(read.cellCount(), original.cellCount());
  for (std::size_t i = 0; i < read.cellCount(); ++i) {
    ASSERT_EQ(read.lowers()[i], original.lowers()[i]);
    ASSERT_EQ(read.levels()[i], original.levels()[i]);
  }
  ASSERT_EQ(read.channels().size(), 3u);
  for (std::size_t c = 0; c < 3; ++c) {
    EXPECT_EQ(read.channels()[c].name, original.channels()[c].name);
    EXPECT_EQ(read.channels()[c].values, original.channels()[c].values);
  }
  EXPECT_EQ(read.transform().origin, original.transform().origin);
  EXPECT_EQ(read.transform().spacing, original.transform().spacing);
  EXPECT_EQ(read.source(), config.string());
}

TEST_F(ExaFormat, AcceptsCommentsBlankLinesAndBricksDirective) {
  const fs::path config = writeSample();
  std::ifstream in(config);
  std::string text((std::istreambuf_iterator<char>(in)), {});
  writeText(config, "# header comment\n\n   \nbricks ignored.bricks  # prebuilt\n" + text);
  EXPECT_EQ(readExa(config).cellCount(), testing::randomAmr(7).cellCount());
}

TEST_F(ExaFormat, RejectsTruncatedCellsFileNamingBothSizes) {
  const fs::path config = writeSample();
  const fs::path cells = dir_ / "sample.cells";
  const auto size = fs::file_size(cells);
  fs::resize_file(cells, size - 3);
  const std::string error = errorOf(config);
  EXPECT_THAT(error, HasSubstr(cells.string()));
  EXPECT_THAT(error,
              HasSubstr("size " + std::to_string(size - 3) + " bytes is not a multiple of 16"));
}

TEST_F(ExaFormat, RejectsScalarCountDifferentFromCellCount) {
  const fs::path config = writeSample();
  const std::size_t cells = testing::randomAmr(7).cellCount();
  const fs::path scalars = dir_ / "sample.vy.scalars";
  fs::resize_file(scalars, (cells - 2) * 4);
  const std::string error = errorOf(config);
  EXPECT_THAT(error, HasSubstr(scalars.string()));
  EXPECT_THAT(error, HasSubstr(std::to_string(cells - 2) + " float32 values"));
  EXPECT_THAT(error, HasSubstr("has " + std::to_string(cells) + " cells"));
}

TEST_F(ExaFormat, RejectsCellsThatOverlapAfterCorruption) {
  const fs::path config = writeSample();
  // Copy cell 0's record over cell 1: a duplicated or overlapping cell.
  std::fstream f(dir_ / "sample.cells", std::ios::in | std::ios::out | std::ios::binary);
  char record[16];
  f.read(record, 16);
  f.seekp(16);
  f.write(record, 16);
  f.close();
  EXPECT_THAT(errorOf(config), HasSubstr(config.string()));
}

TEST_F(ExaFormat, RejectsNegativeLevel) {
  const fs::path config = writeSample();
  std::fstream f(dir_ / "sample.cells", std::ios::in | std::ios::out | std::ios::binary);
  const std::int32_t level = -1;
  f.seekp(12);
  f.write(reinterpret_cast<const char*>(&level), 4);
  f.close();
  EXPECT_THAT(errorOf(config), HasSubstr("cell 0 has level -1"));
}

// Cells are unpacked and checked in parallel: of several bad cells, the first is named,
// wherever they lie.
TEST_F(ExaFormat, NamesTheFirstOfSeveralBadCells) {
  std::vector<std::array<std::int32_t, 4>> cells;
  for (int i = 0; i < 150000; ++i) cells.push_back({2 * (i % 50), 2 * (i / 50), 0, 1});
  cells[140000][3] = 99;
  cells[70000][3] = -7;
  cells[100000][3] = 31;
  EXPECT_THAT(errorOf(writeCells(cells)), HasSubstr("cell 70000 has level -7"));
  cells[70000][3] = 1;
  cells[100000][3] = 1;
  cells[140000][3] = 1;
  cells[4000][3] = 99;
  cells[1234][3] = -7;
  cells[2500][3] = 31;
  EXPECT_THAT(errorOf(writeCells(cells)), HasSubstr("cell 1234 has level -7"));
  cells[1234][3] = 1;
  cells[2500][3] = 1;
  cells[4000][3] = 1;
  cells[3333] = {std::numeric_limits<std::int32_t>::max() - 1, 0, 0, 1};
  cells[4444] = {std::numeric_limits<std::int32_t>::max() - 1, 2, 0, 1};
  EXPECT_THAT(errorOf(writeCells(cells)), HasSubstr("cell 3333 at (2147483646, 0, 0), 2 finest "
                                                    "cells wide, reaches past 2^31 - 1"));
}

TEST_F(ExaFormat, RejectsMalformedConfigWithLineNumbers) {
  writeSample();
  const fs::path config = dir_ / "bad.exa";
  writeText(config, "cells sample.cells\n# fine\nscalars vx sample.vx.scalars\n");
  EXPECT_THAT(errorOf(config), HasSubstr(config.string() + ":3: unknown directive 'scalars'"));
  writeText(config, "cells sample.cells\nscalar vx\n");
  EXPECT_THAT(errorOf(config), HasSubstr(":2: 'scalar' needs a name and a file"));
  writeText(config, "cells sample.cells\nspacing 1 0 1\n");
  EXPECT_THAT(errorOf(config), HasSubstr(":2: 'spacing' must be positive"));
  writeText(config, "cells sample.cells extra\n");
  EXPECT_THAT(errorOf(config), HasSubstr(":1: unexpected 'extra'"));
  writeText(config, "scalar vx sample.vx.scalars\n");
  EXPECT_THAT(errorOf(config), HasSubstr("no 'cells FILE' line"));
  writeText(config, "cells missing.cells\n");
  EXPECT_THAT(errorOf(config), HasSubstr("missing.cells: no such file"));
  writeText(config, std::string("cells sample.cells\ncells \0\0@\n", 29));
  EXPECT_THAT(errorOf(config), HasSubstr(":2: the line holds a NUL byte"));
}

// ---- what the dataset says about itself: time, periodic, length-unit, time-unit -------------

TEST_F(ExaFormat, RoundTripsTimeUnitsAndPeriodicity) {
  bricks::AmrField field = testing::randomAmr(5);
  DatasetInfo info;
  info.format = "Enzo";
  info.time = 0.81751317119117;
  info.timeUnit = "code units (1 = 1.381e+16 s)";
  info.lengthUnit = "code units (1 = 5.615e+23 cm proper at z = 9.991; 1 Mpc/h comoving)";
  info.periodic = {true, false, true};
  info.periodicKnown = true;
  info.finestFileLevel = 7;  // Enzo numbering: not carried, .exa levels are ExaBricks levels
  field.setInfo(info);
  const fs::path config = writeExa(field, dir_ / "described");

  const DatasetInfo read = readExa(config).info();
  EXPECT_EQ(read.format, "ExaBricks");
  EXPECT_EQ(read.time, info.time);
  EXPECT_EQ(read.timeUnit, info.timeUnit);
  EXPECT_EQ(read.lengthUnit, info.lengthUnit);
  EXPECT_TRUE(read.periodicKnown);
  EXPECT_EQ(read.periodic, info.periodic);
  EXPECT_EQ(read.fileLevel(0), 0);
  EXPECT_EQ(read.fileLevel(2), 2);
}

TEST_F(ExaFormat, WithoutTheOptionalLinesNothingIsKnown) {
  const DatasetInfo info = readExa(writeSample()).info();
  EXPECT_FALSE(info.time.has_value());
  EXPECT_FALSE(info.periodicKnown);
  EXPECT_EQ(info.timeUnit, "");
  EXPECT_EQ(info.lengthUnit, "");
  std::ifstream in(dir_ / "sample.exa");
  const std::string text((std::istreambuf_iterator<char>(in)), {});
  EXPECT_THAT(text, ::testing::Not(HasSubstr("periodic")));
  EXPECT_THAT(text, ::testing::Not(HasSubstr("time")));
}

TEST_F(ExaFormat, ReadsHandWrittenLines) {
  writeSample();
  const fs::path config = dir_ / "hand.exa";
  writeText(config,
            "cells sample.cells\ntime -2.5e-3   # before the event\nperiodic 0 1 0\n"
            "length-unit   Mpc / h   \ntime-unit Gyr\n");
  const DatasetInfo info = readExa(config).info();
  EXPECT_EQ(info.time, -2.5e-3);
  EXPECT_EQ(info.periodic, (std::array<bool, 3>{false, true, false}));
  EXPECT_EQ(info.lengthUnit, "Mpc / h");
  EXPECT_EQ(info.timeUnit, "Gyr");
}

TEST_F(ExaFormat, RejectsMalformedInfoLinesWithLineNumbers) {
  writeSample();
  const fs::path config = dir_ / "bad.exa";
  writeText(config, "cells sample.cells\nperiodic 1 0\n");
  EXPECT_THAT(errorOf(config), HasSubstr(config.string() +
                                         ":2: 'periodic' needs three flags 0 or 1 (x y z), got 2"));
  writeText(config, "cells sample.cells\nperiodic 1 0 2\n");
  EXPECT_THAT(errorOf(config), HasSubstr(config.string() + ":2: 'periodic' needs three flags"));
  writeText(config, "cells sample.cells\n\ntime soon\n");
  EXPECT_THAT(errorOf(config),
              HasSubstr(config.string() + ":3: 'time' needs one finite number, got 'soon'"));
  writeText(config, "cells sample.cells\ntime 1.5s\n");
  EXPECT_THAT(errorOf(config), HasSubstr(":2: 'time' needs one finite number, got '1.5s'"));
  writeText(config, "cells sample.cells\ntime 1 2\n");
  EXPECT_THAT(errorOf(config), HasSubstr(":2: unexpected '2' after 'time'"));
  writeText(config, "cells sample.cells\ntime\n");
  EXPECT_THAT(errorOf(config), HasSubstr(":2: 'time' needs one finite number"));
  writeText(config, "cells sample.cells\nlength-unit   # none\n");
  EXPECT_THAT(errorOf(config), HasSubstr(":2: 'length-unit' needs a text"));
}

TEST_F(ExaFormat, RefusesToWriteAUnitThatALineCannotHold) {
  bricks::AmrField field = testing::randomAmr(5);
  DatasetInfo info;
  info.lengthUnit = "furlongs # per fortnight";
  field.setInfo(info);
  const std::string error = testing::inputErrorOf([&] { writeExa(field, dir_ / "unit"); });
  EXPECT_THAT(error, HasSubstr((dir_ / "unit.exa").string()));
  EXPECT_THAT(error, HasSubstr("length-unit"));
  EXPECT_FALSE(fs::exists(dir_ / "unit.cells"));
}

TEST_F(ExaFormat, LoadInputDispatchesAndRejectsUnknownInputs) {
  const fs::path config = writeSample();
  EXPECT_EQ(loadInput(config.string(), {}).cellCount(), testing::randomAmr(7).cellCount());
  try {
    loadInput((dir_ / "nothing.exa").string(), {});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("no such file"));
  }
  writeText(dir_ / "data.xyz", "1 2 3\n");
  try {
    loadInput((dir_ / "data.xyz").string(), {});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("format not recognised"));
  }
}

// ---- hardening: paths that are not files, sizes, overflow, transforms, values, writes --------

TEST_F(ExaFormat, DirectoriesAndFifosAreRefusedByNameBeforeOpening) {
  const fs::path config = writeSample();
  const fs::path scalars = dir_ / "sample.vy.scalars";
  fs::remove(scalars);
  fs::create_directory(scalars);
  EXPECT_THAT(errorOf(config), HasSubstr(scalars.string() + ": is a directory, not a file"));
  fs::remove(scalars);
  testing::makeFifo(scalars);
  EXPECT_THAT(testing::inputErrorWithoutHanging(scalars, [&] { readExa(config); }),
              HasSubstr(scalars.string() + ": is a FIFO (named pipe), not a regular file"));

  const fs::path cells = dir_ / "sample.cells";
  fs::remove(cells);
  testing::makeFifo(cells);
  EXPECT_THAT(testing::inputErrorWithoutHanging(cells, [&] { readExa(config); }),
              HasSubstr(cells.string() + ": is a FIFO"));
  const fs::path fifoConfig = dir_ / "fifo.exa";
  testing::makeFifo(fifoConfig);
  EXPECT_THAT(testing::inputErrorWithoutHanging(fifoConfig, [&] { readExa(fifoConfig); }),
              HasSubstr(fifoConfig.string() + ": is a FIFO"));
}

// Sparse files: their sizes claim a terabyte; the reader must refuse them from the size alone.
TEST_F(ExaFormat, SizesAreCheckedBeforeAnythingIsAllocated) {
  const fs::path config = writeSample();
  const std::size_t cells = testing::randomAmr(7).cellCount();
  const fs::path scalars = dir_ / "sample.vx.scalars";
  const std::uintmax_t terabyte = std::uintmax_t{1} << 40;
  fs::resize_file(scalars, terabyte);
  EXPECT_THAT(errorOf(config), AllOf(HasSubstr(scalars.string()),
                                     HasSubstr("holds " + std::to_string(terabyte) + " bytes"),
                                     HasSubstr("has " + std::to_string(cells) + " cells")));
  fs::resize_file(dir_ / "sample.cells", terabyte);
  EXPECT_THAT(errorOf(config), AllOf(HasSubstr((dir_ / "sample.cells").string()),
                                     HasSubstr("holds 68719476736 cells, more than the "
                                               "2147483648 accepted")));
}

TEST_F(ExaFormat, ACellsFileWithAHoleIsRefusedBeforeItsCellsAreHeld) {
  const fs::path config = writeSample();
  const fs::path cells = dir_ / "sample.cells";
  std::ifstream in(cells, std::ios::binary);
  const std::string head(std::istreambuf_iterator<char>(in), {});
  // 5 GiB declared, 335 million cells, of which the file holds the sample's.
  if (!testing::makeSparseFile(cells, head, std::uintmax_t(5) << 30))
    GTEST_SKIP() << "the file system of " << dir_ << " does not report holes (SEEK_HOLE)";
  EXPECT_THAT(errorOf(config), AllOf(HasSubstr(cells.string() + ": the cells file has a hole"),
                                     HasSubstr("of 5368709120")));
}

TEST_F(ExaFormat, CellsNearIntMaxAreRefusedWithoutOverflow) {
  const std::int32_t intMax = std::numeric_limits<std::int32_t>::max();
  const std::int32_t intMin = std::numeric_limits<std::int32_t>::min();
  fs::path config = writeCells({{0, 0, 0, 0}, {intMax, 0, 0, 0}});
  EXPECT_THAT(errorOf(config),
              AllOf(HasSubstr((dir_ / "raw.cells").string()),
                    HasSubstr("cell 1 at (2147483647, 0, 0), 1 finest cells wide, reaches past "
                              "2^31 - 1")));
  config = writeCells({{intMin, 0, 0, 0}, {intMax - 1, 0, 0, 0}});
  EXPECT_THAT(errorOf(config),
              AllOf(HasSubstr((dir_ / "raw.cells").string()),
                    HasSubstr("the cells span 4294967295 finest cells along axis x")));
  // Aligned, in range and far from the origin: read as they are.
  config = writeCells({{intMax - 1, 0, 0, 0}, {intMax - 3, 0, 0, 1}});
  const bricks::AmrField field = readExa(config);
  EXPECT_EQ(field.bounds().lower, glm::ivec3(intMax - 3, 0, 0));
  EXPECT_EQ(field.bounds().upper, glm::ivec3(intMax, 2, 2));
}

TEST_F(ExaFormat, TransformMustPlaceCellsAtFiniteDistinctPositions) {
  const std::vector<std::array<std::int32_t, 4>> cells{{0, 0, 0, 0}, {1, 0, 0, 0}};
  fs::path config = writeCells(cells, "origin 1e308 0 0\n");
  EXPECT_THAT(errorOf(config), AllOf(HasSubstr(config.string()), HasSubstr("origin (line 3)"),
                                     HasSubstr("along x reaches 1e+308")));
  config = writeCells(cells, "spacing 1e300 1 1\n");
  EXPECT_THAT(errorOf(config), AllOf(HasSubstr("spacing (line 3)"),
                                     HasSubstr("the spacing along x is 1e+300, outside")));
  config = writeCells(cells, "origin 9e36 0 0\nspacing 1e36 1 1\n");
  EXPECT_THAT(errorOf(config), HasSubstr("along x reaches 1.1e+37, beyond the 1e+37 that float32 "
                                         "positions can hold"));
  config = writeCells(cells, "spacing 1 1e-320 1\n");
  EXPECT_THAT(errorOf(config),
              AllOf(HasSubstr(config.string() + ":3: 'spacing' must be positive and not "
                                                "subnormal, got 1e-320 along y")));
  config = writeCells(cells, "origin 1e12 0 0\nspacing 1e-6 1 1\n");
  EXPECT_THAT(errorOf(config), HasSubstr("neighbouring cells would share a position"));
  config = writeCells(cells, "origin 0 nan 0\n");
  EXPECT_THAT(errorOf(config), HasSubstr(":3: 'origin' y is not a finite number: 'nan'"));
  config = writeCells(cells, "origin 1e400 0 0\n");
  EXPECT_THAT(errorOf(config), HasSubstr(":3: 'origin' x is not a finite number: '1e400'"));
  config = writeCells(cells, "origin -1e30 0 0\nspacing 1e25 1 1\n");
  EXPECT_EQ(readExa(config).transform().spacing.x, 1e25);
}

TEST_F(ExaFormat, NonFiniteValuesNameTheFileTheChannelAndTheCell) {
  const fs::path config = writeSample();
  const fs::path scalars = dir_ / "sample.vy.scalars";
  const bricks::AmrField field = testing::randomAmr(7);
  const glm::ivec3 corner = field.lowers()[5];
  poke(scalars, 5, std::numeric_limits<float>::quiet_NaN());
  EXPECT_THAT(errorOf(config),
              AllOf(HasSubstr(scalars.string() +
                              ": channel 'vy': the value of cell 5 (lower "
                              "corner " +
                              std::to_string(corner.x) + ", " + std::to_string(corner.y) + ", " +
                              std::to_string(corner.z) + ") is not a number")));
  poke(scalars, 5, 0.5f);
  poke(scalars, 9, -std::numeric_limits<float>::infinity());
  EXPECT_THAT(errorOf(config), HasSubstr("the value of cell 9"));
  EXPECT_THAT(errorOf(config), HasSubstr("is infinite"));
}

// The cells first, without channels, then one channel at a time: the same cells and values as
// readExa's; every scalars file is checked for its size up front, each channel's values when it
// is read.
TEST_F(ExaFormat, CellsFirstThenChannelsOneAtATimeGiveReadExasField) {
  const fs::path config = writeSample();
  const bricks::AmrField whole = readExa(config);
  const ExaCells cells = readExaCells(config);
  EXPECT_TRUE(cells.field.channels().empty());
  ASSERT_EQ(cells.field.cellCount(), whole.cellCount());
  EXPECT_TRUE(
      std::equal(whole.lowers().begin(), whole.lowers().end(), cells.field.lowers().begin()));
  EXPECT_TRUE(
      std::equal(whole.levels().begin(), whole.levels().end(), cells.field.levels().begin()));
  ASSERT_EQ(cells.channels.size(), whole.channels().size());
  for (std::size_t c = 0; c < cells.channels.size(); ++c) {
    EXPECT_EQ(cells.channels[c].name, whole.channels()[c].name);
    EXPECT_EQ(readExaChannel(cells.channels[c]), whole.channels()[c].values);
    std::vector<float> into(cells.field.cellCount(), -1.0f);
    readExaChannelInto(cells.channels[c], into);
    EXPECT_EQ(into, whole.channels()[c].values);
  }
  std::vector<float> tooShort(cells.field.cellCount() - 1);
  EXPECT_THAT(testing::inputErrorOf([&] { readExaChannelInto(cells.channels[0], tooShort); }),
              HasSubstr("values asked for of a channel of"));

  poke(dir_ / "sample.vz.scalars", 3, std::numeric_limits<float>::infinity());
  const ExaCells poked = readExaCells(config);  // values are not read yet
  EXPECT_THAT(testing::inputErrorOf([&] { readExaChannel(poked.channels[2]); }),
              HasSubstr((dir_ / "sample.vz.scalars").string() +
                        ": channel 'vz': the value of cell 3 is infinite"));
  fs::resize_file(dir_ / "sample.vy.scalars", 8);
  EXPECT_THAT(testing::inputErrorOf([&] { readExaCells(config); }),
              HasSubstr((dir_ / "sample.vy.scalars").string() + ": holds 8 bytes"));
}

TEST_F(ExaFormat, AFailedWriteLeavesNoFile) {
  const bricks::AmrField field = testing::randomAmr(7);
  // The .exa comes last: a directory in its place fails the set after the data files were done.
  fs::create_directory(dir_ / "out.exa");
  EXPECT_THAT(testing::inputErrorOf([&] { writeExa(field, dir_ / "out"); }),
              HasSubstr((dir_ / "out.exa").string() + ": cannot write the file"));
  std::vector<std::string> left;
  for (const auto& entry : fs::directory_iterator(dir_))
    left.push_back(entry.path().filename().string());
  EXPECT_THAT(left, ::testing::ElementsAre("out.exa"));
  EXPECT_TRUE(fs::is_directory(dir_ / "out.exa"));

  // A channel whose file name is too long fails after the cells file was begun.
  fs::remove(dir_ / "out.exa");
  bricks::AmrField longName({field.lowers().begin(), field.lowers().end()},
                            {field.levels().begin(), field.levels().end()},
                            {{std::string(300, 'v'), field.channels()[0].values}},
                            field.transform(), "long");
  EXPECT_THAT(testing::inputErrorOf([&] { writeExa(longName, dir_ / "out"); }),
              HasSubstr("cannot write the file: File name too long"));
  EXPECT_TRUE(fs::is_empty(dir_));
}

TEST_F(ExaFormat, RefusesNamesThatTheConfigCannotHoldBeforeWriting) {
  const bricks::AmrField field = testing::randomAmr(7);
  bricks::AmrField spaced({field.lowers().begin(), field.lowers().end()},
                          {field.levels().begin(), field.levels().end()},
                          {{"x velocity", field.channels()[0].values}}, field.transform(), "s");
  EXPECT_THAT(testing::inputErrorOf([&] { writeExa(spaced, dir_ / "out"); }),
              AllOf(HasSubstr((dir_ / "out.exa").string()),
                    HasSubstr("the channel name 'x velocity' is empty or holds a blank")));
  EXPECT_TRUE(fs::is_empty(dir_));
}

}  // namespace
}  // namespace amrstream::formats
