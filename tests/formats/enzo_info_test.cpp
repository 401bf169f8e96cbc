// What an Enzo dataset says about itself: the real moving7 snapshot checked against its parameter
// file read here as text and against cosmology (its time unit must turn InitialTime into the age
// of its Einstein-de Sitter universe at its redshift), and parameter files written here.

#include "formats/enzo/enzo_info.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "formats/enzo/enzo_reader.hpp"
#include "input_error_of.hpp"
#include "temp_dir_test.hpp"

namespace amrstream::formats {
namespace {

namespace fs = std::filesystem;
using ::testing::AllOf;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

const fs::path kRealParameters =
    fs::path(AMRSTREAM_REAL_DATA_DIR) / "enzo-moving7" / "DD0010" / "moving7_0010";

// `Key = value` of a parameter file, read independently of the reader ('#' lines included, with
// the '#', as Enzo writes some values commented out).
std::map<std::string, std::string> parameterText(const fs::path& file) {
  std::map<std::string, std::string> values;
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);) {
    std::istringstream words(line);
    std::string key, equals, value, rest;
    if (!(words >> key >> equals) || equals != "=") continue;
    std::getline(words, rest);
    values[key] = rest;
  }
  return values;
}

double number(const std::map<std::string, std::string>& text, const std::string& key) {
  return std::stod(text.at(key));
}

class EnzoInfoReal : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!fs::exists(kRealParameters))
      GTEST_SKIP() << "real Enzo data absent: " << kRealParameters
                   << " (shared/data/real not checked out)";
  }
};

TEST_F(EnzoInfoReal, TimePeriodicityAndLevelsAsTheParameterFileSays) {
  const auto text = parameterText(kRealParameters);
  const bricks::AmrField field = readEnzo(kRealParameters);
  const DatasetInfo& info = field.info();
  EXPECT_EQ(info.format, "Enzo");
  EXPECT_EQ(info.time, number(text, "InitialTime"));
  EXPECT_NEAR(*info.time, 0.81751317119117, 1e-14);
  EXPECT_EQ(text.at("LeftFaceBoundaryCondition"), " 3 3 3 ");
  EXPECT_EQ(text.at("RightFaceBoundaryCondition"), " 3 3 3 ");
  EXPECT_TRUE(info.periodicKnown);
  EXPECT_THAT(info.periodic, ElementsAre(true, true, true));
  // README: grids on Enzo levels 0 (root) .. 7; our level 0 is the finest.
  EXPECT_EQ(info.levelName, "Enzo level (0 = root grid)");
  EXPECT_EQ(info.fileLevel(0), 7);
  EXPECT_EQ(info.fileLevel(field.coarsestLevel()), 0);
}

TEST_F(EnzoInfoReal, CodeUnitsSizedByTheCosmology) {
  const auto text = parameterText(kRealParameters);
  ASSERT_EQ(number(text, "ComovingCoordinates"), 1.0);
  ASSERT_EQ(number(text, "CosmologyOmegaMatterNow"), 1.0);
  ASSERT_EQ(number(text, "CosmologyOmegaLambdaNow"), 0.0);
  const DatasetInfo info = readEnzo(kRealParameters).info();
  ASSERT_TRUE(info.timeUnitSeconds.has_value());
  ASSERT_TRUE(info.lengthUnitCentimetres.has_value());
  EXPECT_THAT(info.timeUnit, HasSubstr("code units (1 = "));
  EXPECT_THAT(info.lengthUnit, HasSubstr("code units (1 = "));

  // Einstein-de Sitter: the universe's age at redshift z is 2 / (3 H0 (1 + z)^1.5), and Enzo's
  // time counts from the big bang, so InitialTime in seconds must be that age.
  const double hubbleNow = number(text, "CosmologyHubbleConstantNow") * 1e7 / 3.0856775814913673e24;
  const double z = number(text, "CosmologyCurrentRedshift");
  const double age = 2.0 / (3.0 * hubbleNow * std::pow(1.0 + z, 1.5));
  EXPECT_NEAR(*info.time * *info.timeUnitSeconds / age, 1.0, 1e-3);

  // The file's own velocity conversion (commented out by Enzo 1.3): comoving length over time
  // times the initial expansion factor 1 / (1 + z_initial).
  const double zInitial = number(text, "CosmologyInitialRedshift");
  const double velocityUnit =
      *info.lengthUnitCentimetres * (1.0 + z) / (1.0 + zInitial) / *info.timeUnitSeconds;
  EXPECT_NEAR(velocityUnit / number(text, "#DataCGSConversionFactor[2]"), 1.0, 1e-3);
}

class EnzoInfoWritten : public testing::TempDirTest {
 protected:
  fs::path write(const std::string& text) {
    const fs::path path = dir_ / "params";
    std::ofstream(path) << text;
    return path;
  }
};

TEST_F(EnzoInfoWritten, NonCosmologicalUnitsFromLengthUnitsAndTimeUnits) {
  const EnzoParameters parameters(
      write("InitialTime = 2.5\nComovingCoordinates = 0\n"
            "LengthUnits = 3.0857e+21\nTimeUnits = 3.15e+13\n"
            "LeftFaceBoundaryCondition  = 3 0 3\n"
            "RightFaceBoundaryCondition = 3 3 1\n"));
  const DatasetInfo info = readEnzoInfo(&parameters, 4);
  EXPECT_EQ(info.time, 2.5);
  EXPECT_EQ(info.lengthUnitCentimetres, 3.0857e21);
  EXPECT_EQ(info.timeUnitSeconds, 3.15e13);
  EXPECT_EQ(info.lengthUnit, "code units (1 = 3.086e+21 cm)");
  EXPECT_EQ(info.timeUnit, "code units (1 = 3.15e+13 s)");
  EXPECT_TRUE(info.periodicKnown);
  EXPECT_THAT(info.periodic, ElementsAre(true, false, false));
  EXPECT_EQ(info.fileLevel(0), 4);
}

TEST_F(EnzoInfoWritten, FieldUnitsFromDataUnitsElseTheCgsConversionFactor) {
  const EnzoParameters parameters(
      write("DataLabel[0] = Density\nDataUnits[0] = none\n"
            "#DataCGSConversionFactor[0] = 6.24041e-27\n"
            "DataLabel[1] = TotalEnergy\nDataUnits[1] = none\n"
            "DataLabel[2] = x-velocity\nDataUnits[2] = none\n"
            "#DataCGSConversionFactor[2] = 4.06287e+07\n"
            "DataLabel[3] = Metal_Density\nDataUnits[3] = none\n"
            "#DataCGSConversionFactor[3] = 6.24041e-27\n"
            "DataLabel[4] = Bx\nDataUnits[4] = G\n"));
  const DatasetInfo info = readEnzoInfo(&parameters, 0);
  EXPECT_EQ(unitOf(info, "Density"), "code units (1 = 6.24e-27 g/cm**3)");
  EXPECT_EQ(unitOf(info, "x-velocity"), "code units (1 = 4.063e+07 cm/s)");
  EXPECT_EQ(unitOf(info, "TotalEnergy"), "");    // no factor stated
  EXPECT_EQ(unitOf(info, "Metal_Density"), "");  // a label whose CGS unit is not fixed
  EXPECT_EQ(unitOf(info, "Bx"), "G");            // as DataUnits states it
}

TEST_F(EnzoInfoWritten, UnstatedValuesStayUnknown) {
  const EnzoParameters parameters(write("TopGridRank = 3\n"));
  const DatasetInfo info = readEnzoInfo(&parameters, 2);
  EXPECT_FALSE(info.time.has_value());
  EXPECT_FALSE(info.periodicKnown);
  EXPECT_EQ(info.lengthUnit, "code units");
  EXPECT_FALSE(info.lengthUnitCentimetres.has_value());
  const DatasetInfo withoutFile = readEnzoInfo(nullptr, 2);
  EXPECT_EQ(withoutFile.format, "Enzo");
  EXPECT_EQ(withoutFile.lengthUnit, "");
  EXPECT_EQ(withoutFile.fileLevel(2), 0);
}

TEST_F(EnzoInfoWritten, MalformedValuesNameTheFileAndTheKey) {
  const fs::path badTime = write("InitialTime = soon\n");
  EXPECT_THAT(testing::inputErrorOf([&] {
                const EnzoParameters parameters(badTime);
                readEnzoInfo(&parameters, 0);
              }),
              AllOf(HasSubstr(badTime.string()), HasSubstr("InitialTime"), HasSubstr("soon")));
  const fs::path badFaces =
      write("LeftFaceBoundaryCondition = 3 3\nRightFaceBoundaryCondition = 3 3 3\n");
  EXPECT_THAT(testing::inputErrorOf([&] {
                const EnzoParameters parameters(badFaces);
                readEnzoInfo(&parameters, 0);
              }),
              AllOf(HasSubstr(badFaces.string()), HasSubstr("LeftFaceBoundaryCondition"),
                    HasSubstr("3 numbers")));
}

}  // namespace
}  // namespace amrstream::formats
