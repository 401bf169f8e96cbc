// ExaBricks files: a written dataset reads back identically, with its time, units and periodic
// axes; truncated, inconsistent and malformed files are rejected with errors naming the file (and
// line) and the numbers involved.

#include "formats/exa_format.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <fstream>

#include "formats/load_input.hpp"
#include "input_error_of.hpp"
#include "random_amr.hpp"
#include "temp_dir_test.hpp"
#include "util/input_error.hpp"

namespace amrstream::formats {
namespace {

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
  EXPECT_THAT(errorOf(config), HasSubstr("missing.cells: cannot open the file"));
}

// ---- what the dataset says about itself: time, periodic, length-unit, time-unit -------------

TEST_F(ExaFormat, RoundTripsTimeUnitsAndPeriodicity) {
  bricks::AmrField field = testing::randomAmr(5);
  bricks::DatasetInfo info;
  info.format = "Enzo";
  info.time = 0.81751317119117;
  info.timeUnit = "code units (1 = 1.381e+16 s)";
  info.lengthUnit = "code units (1 = 5.615e+23 cm proper at z = 9.991; 1 Mpc/h comoving)";
  info.periodic = {true, false, true};
  info.periodicKnown = true;
  info.finestFileLevel = 7;  // Enzo numbering: not carried, .exa levels are ExaBricks levels
  field.setInfo(info);
  const fs::path config = writeExa(field, dir_ / "described");

  const bricks::DatasetInfo read = readExa(config).info();
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
  const bricks::DatasetInfo info = readExa(writeSample()).info();
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
  const bricks::DatasetInfo info = readExa(config).info();
  EXPECT_EQ(info.time, -2.5e-3);
  EXPECT_EQ(info.periodic, (std::array<bool, 3>{false, true, false}));
  EXPECT_EQ(info.lengthUnit, "Mpc / h");
  EXPECT_EQ(info.timeUnit, "Gyr");
}

TEST_F(ExaFormat, RejectsMalformedInfoLinesWithLineNumbers) {
  writeSample();
  const fs::path config = dir_ / "bad.exa";
  writeText(config, "cells sample.cells\nperiodic 1 0\n");
  EXPECT_THAT(errorOf(config),
              HasSubstr(config.string() + ":2: 'periodic' needs three flags 0 or 1 (x y z), got 2"));
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
  bricks::DatasetInfo info;
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
    EXPECT_THAT(e.what(), HasSubstr("unknown input format"));
  }
}

}  // namespace
}  // namespace amrstream::formats
