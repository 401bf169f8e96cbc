// DatasetInfo: the file's level numbers from internal ones (counting down, up, or per level), the
// field's default numbering, and the one-line texts of time, units and periodic axes.

#include "amrstream/dataset_info.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "bricks/amr_field.hpp"

namespace amrstream::bricks {
namespace {

TEST(DatasetInfo, FileLevelsCountDownFromTheFinest) {
  DatasetInfo flash;
  flash.finestFileLevel = 5;  // refine levels 1 (root) .. 5
  flash.levelsCountDown = true;
  EXPECT_EQ(flash.fileLevel(0), 5);
  EXPECT_EQ(flash.fileLevel(4), 1);
}

TEST(DatasetInfo, FileLevelsCountUpFromTheFinest) {
  DatasetInfo exa;
  exa.finestFileLevel = 0;
  exa.levelsCountDown = false;
  EXPECT_EQ(exa.fileLevel(0), 0);
  EXPECT_EQ(exa.fileLevel(3), 3);
}

TEST(DatasetInfo, PerLevelTableOverridesTheFormula) {
  // Three AMReX levels 4 apart: cell widths 16, 4 and 1 finest cells are internal levels 4, 2, 0.
  DatasetInfo amrex;
  amrex.finestFileLevel = 2;
  amrex.fileLevelOfInternal = {2, -1, 1, -1, 0};
  EXPECT_EQ(amrex.fileLevel(0), 2);
  EXPECT_EQ(amrex.fileLevel(2), 1);
  EXPECT_EQ(amrex.fileLevel(4), 0);
  EXPECT_EQ(amrex.fileLevel(1), -1);
  EXPECT_EQ(amrex.fileLevel(7), -1);
}

TEST(DatasetInfo, FieldNumbersLevelsFinestFirstUntilItIsTold) {
  AmrField field({{0, 0, 0}, {2, 0, 0}}, {0, 1}, {}, {}, "two cells");
  EXPECT_EQ(field.info().fileLevel(1), 1);
  EXPECT_FALSE(field.info().periodicKnown);
  EXPECT_FALSE(field.info().time.has_value());

  DatasetInfo info;
  info.format = "Enzo";
  info.time = 0.5;
  info.finestFileLevel = 7;
  field.setInfo(info);
  EXPECT_EQ(field.info().format, "Enzo");
  EXPECT_EQ(field.info().time, 0.5);
  EXPECT_EQ(field.info().fileLevel(1), 6);
}

TEST(DatasetInfo, TimeAndUnitsClauseNamesOnlyWhatIsKnown) {
  DatasetInfo info;
  EXPECT_EQ(timeAndUnitsClause(info), "");
  info.time = 0.8175;
  EXPECT_EQ(timeAndUnitsClause(info), ", t = 0.8175");
  info.timeUnit = "code units (1 = 1.4e+16 s)";
  info.lengthUnit = "cm";
  EXPECT_EQ(timeAndUnitsClause(info), ", t = 0.8175 code units (1 = 1.4e+16 s), lengths in cm");
}

TEST(DatasetInfo, PeriodicAxesText) {
  DatasetInfo info;
  EXPECT_EQ(periodicAxesText(info), "unknown");
  info.periodicKnown = true;
  EXPECT_EQ(periodicAxesText(info), "none");
  info.periodic = {true, false, true};
  EXPECT_EQ(periodicAxesText(info), "x z");
}

}  // namespace
}  // namespace amrstream::bricks
