#include "output/vtp_writer.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <ostream>
#include <set>
#include <stdexcept>
#include <string>

#include "every_compression.hpp"
#include "sample_traces.hpp"
#include "vtp_test_reader.hpp"

// Readable failure messages for positions and vectors.
namespace glm {
void PrintTo(const vec3& v, std::ostream* os) {
  *os << '(' << v.x << ", " << v.y << ", " << v.z << ')';
}
}  // namespace glm

namespace amrstream::testing {
namespace {

namespace fs = std::filesystem;

// Every test runs for each compression: the test reader decompresses on its own (zlib, LZ4).
class VtpWriter : public ::testing::TestWithParam<output::Compression> {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = info->name();  // "Test/zlib": one directory, not a parent and a child
    std::replace(name.begin(), name.end(), '/', '-');
    dir_ = fs::temp_directory_path() / ("amrstream-vtp-" + std::to_string(::getpid()) + "-" + name);
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Names in the output directory, so tests can see that no temporary file was left.
  std::set<std::string> entries() const {
    std::set<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir_)) {
      names.insert(entry.path().filename().string());
    }
    return names;
  }

  output::VtpWriteOptions options() const {
    output::VtpWriteOptions options;
    options.compression = GetParam();
    return options;
  }

  VtpFile writeAndRead(const flow::TraceSet& traces,
                       const std::vector<output::FieldDataArray>& fieldData = {}) {
    const fs::path path = dir_ / "traces.vtp";
    output::VtpWriteOptions withFieldData = options();
    withFieldData.fieldData = fieldData;
    output::writeVtp(path, traces, withFieldData);
    EXPECT_EQ(entries(), std::set<std::string>{"traces.vtp"});
    return readVtp(path);
  }

  fs::path dir_;
};

std::string readText(const fs::path& path) {
  std::ifstream stream(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(stream), std::istreambuf_iterator<char>()};
}

TEST_P(VtpWriter, DeclaresPolyDataWithAppendedArraysInTheirSections) {
  const VtpFile vtp = writeAndRead(sampleTraces(kSamplePointCounts));

  XmlAttributes vtkFile{{"type", "PolyData"},
                        {"version", "1.0"},
                        {"byte_order", "LittleEndian"},
                        {"header_type", "UInt64"}};
  if (GetParam() == output::Compression::ZLib) vtkFile["compressor"] = "vtkZLibDataCompressor";
  if (GetParam() == output::Compression::LZ4) vtkFile["compressor"] = "vtkLZ4DataCompressor";
  EXPECT_EQ(vtp.vtkFile, vtkFile);
  // 3 + 1 + 5 + 2 trace points; the 1-point trace is written as its point twice.
  EXPECT_EQ(vtp.piece, (XmlAttributes{{"NumberOfPoints", "12"},
                                      {"NumberOfVerts", "0"},
                                      {"NumberOfLines", "4"},
                                      {"NumberOfStrips", "0"},
                                      {"NumberOfPolys", "0"}}));
  EXPECT_EQ(vtp.pointData,
            (XmlAttributes{{"Scalars", "IntegrationTime"}, {"Vectors", "velocity"}}));

  struct Expected {
    const char* section;
    const char* name;
    const char* type;
    int components;
    std::size_t bytes;
  };
  // vtkStreamTracer's order: the input's arrays, IntegrationTime; then ours.
  const Expected expected[] = {
      {"PointData", "velocity", "Float32", 3, 12 * 12},
      {"PointData", "IntegrationTime", "Float32", 1, 12 * 4},
      {"PointData", "Speed", "Float32", 1, 12 * 4},
      {"CellData", "ReasonForTermination", "Int32", 1, 4 * 4},
      {"CellData", "SeedIds", "Int32", 1, 4 * 4},
      {"Points", "Points", "Float32", 3, 12 * 12},
      {"Lines", "connectivity", "Int64", 1, 12 * 8},
      {"Lines", "offsets", "Int64", 1, 4 * 8},
  };
  ASSERT_EQ(vtp.arrays.size(), std::size(expected));
  for (std::size_t i = 0; i < std::size(expected); ++i) {
    SCOPED_TRACE(expected[i].name);
    const VtpArray& array = vtp.arrays[i];
    EXPECT_EQ(array.section, expected[i].section);
    EXPECT_EQ(array.name(), expected[i].name);
    EXPECT_EQ(array.type(), expected[i].type);
    EXPECT_EQ(array.components(), expected[i].components);
    EXPECT_EQ(array.bytes.size(), expected[i].bytes);
  }
}

// Points the file holds for a trace of `count` points: a 1-point trace's point twice.
std::uint32_t writtenPoints(std::uint32_t count) { return count == 1 ? 2 : count; }

TEST_P(VtpWriter, WritesOnlyTheValidPointsOfEachTrace) {
  const VtpFile vtp = writeAndRead(sampleTraces(kSamplePointCounts));
  const auto points = vtp.array("Points", "Points").values<glm::vec3>();
  const auto times = vtp.array("PointData", "IntegrationTime").values<float>();
  const auto vectors = vtp.array("PointData", "velocity").values<glm::vec3>();
  ASSERT_EQ(points.size(), 12u);
  ASSERT_EQ(times.size(), 12u);
  ASSERT_EQ(vectors.size(), 12u);

  std::size_t i = 0;
  for (std::uint32_t seed = 0; seed < kSamplePointCounts.size(); ++seed) {
    for (std::uint32_t written = 0; written < writtenPoints(kSamplePointCounts[seed]);
         ++written, ++i) {
      const std::uint32_t point = std::min(written, kSamplePointCounts[seed] - 1);
      SCOPED_TRACE(::testing::Message() << "seed " << seed << " point " << written);
      EXPECT_EQ(points[i], samplePosition(seed, point));
      EXPECT_EQ(times[i], sampleTime(seed, point));
      EXPECT_EQ(vectors[i], sampleVector(seed, point));
    }
  }
}

TEST_P(VtpWriter, MakesOnePolylinePerTraceThroughItsPointsInOrder) {
  const VtpFile vtp = writeAndRead(sampleTraces(kSamplePointCounts));
  EXPECT_EQ(vtp.array("Lines", "connectivity").values<std::int64_t>(),
            (std::vector<std::int64_t>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11}));
  // VTK XML offsets are the end of each cell's ids; the 1-point trace is a 2-point line.
  EXPECT_EQ(vtp.array("Lines", "offsets").values<std::int64_t>(),
            (std::vector<std::int64_t>{3, 5, 10, 12}));
}

TEST_P(VtpWriter, SpeedIsTheMagnitudeOfTheVector) {
  const VtpFile vtp = writeAndRead(sampleTraces(kSamplePointCounts));
  const auto speeds = vtp.array("PointData", "Speed").values<float>();
  const auto vectors = vtp.array("PointData", "velocity").values<glm::vec3>();
  ASSERT_EQ(speeds.size(), vectors.size());
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    const glm::dvec3 v(vectors[i]);
    EXPECT_FLOAT_EQ(speeds[i], static_cast<float>(std::sqrt(glm::dot(v, v)))) << "point " << i;
  }
  EXPECT_EQ(speeds[0], 5.0f);  // (3, 4, 0)
  EXPECT_EQ(speeds[3], 0.0f);  // trace 1, a single point with a zero vector, written twice
  EXPECT_EQ(speeds[4], 0.0f);
}

TEST_P(VtpWriter, CellsCarryTheirSeedIdAndReason) {
  const VtpFile vtp = writeAndRead(sampleTraces(kSamplePointCounts));
  EXPECT_EQ(vtp.array("CellData", "SeedIds").values<std::int32_t>(),
            (std::vector<std::int32_t>{0, 1, 2, 3}));
  EXPECT_EQ(vtp.array("CellData", "ReasonForTermination").values<std::int32_t>(),
            (std::vector<std::int32_t>{sampleReason(0), sampleReason(1), sampleReason(2),
                                       sampleReason(3)}));
}

TEST_P(VtpWriter, NamesTheVectorVectorsWhenTheTraceSetHasNoName) {
  const VtpFile vtp = writeAndRead(sampleTraces(kSamplePointCounts, ""));
  EXPECT_EQ(vtp.pointData.at("Vectors"), "Vectors");
  EXPECT_EQ(vtp.array("PointData", "Vectors").components(), 3);
}

TEST_P(VtpWriter, EscapesTheVectorNameInXml) {
  const char* name = "u<v> & \"w\"";
  const VtpFile vtp = writeAndRead(sampleTraces(kSamplePointCounts, name));
  EXPECT_EQ(vtp.pointData.at("Vectors"), name);
  EXPECT_EQ(vtp.array("PointData", name).components(), 3);
  EXPECT_NE(readText(dir_ / "traces.vtp").find("u&lt;v&gt; &amp; &quot;w&quot;"),
            std::string::npos);
}

TEST_P(VtpWriter, RenamesAVectorThatWouldCollideWithSpeedOrTime) {
  for (const std::string name : {"Speed", "IntegrationTime"}) {
    const VtpFile vtp = writeAndRead(sampleTraces(kSamplePointCounts, name.c_str()));
    EXPECT_EQ(vtp.pointData.at("Vectors"), name + "_vector");
    EXPECT_EQ(vtp.array("PointData", name + "_vector").components(), 3);
    EXPECT_EQ(vtp.array("PointData", name).components(), 1);
  }
}

TEST_P(VtpWriter, AnEmptyTraceSetIsAValidFileWithNoPointsOrLines) {
  const VtpFile vtp = writeAndRead(sampleTraces({}));
  EXPECT_EQ(vtp.piece.at("NumberOfPoints"), "0");
  EXPECT_EQ(vtp.piece.at("NumberOfLines"), "0");
  ASSERT_EQ(vtp.arrays.size(), 8u);
  for (const VtpArray& array : vtp.arrays) EXPECT_TRUE(array.bytes.empty()) << array.name();
}

// VTK cannot use a line of fewer than 2 points (VTK 9.1 crashes in GetCellPoints on one).
TEST_P(VtpWriter, ATraceThatEndsAtItsSeedIsItsPointTwiceInOneLine) {
  const VtpFile vtp = writeAndRead(sampleTraces({2, 1, 1}));
  EXPECT_EQ(vtp.piece.at("NumberOfPoints"), "6");
  EXPECT_EQ(vtp.piece.at("NumberOfLines"), "3");
  EXPECT_EQ(vtp.array("Lines", "offsets").values<std::int64_t>(),
            (std::vector<std::int64_t>{2, 4, 6}));
  EXPECT_EQ(vtp.array("CellData", "SeedIds").values<std::int32_t>(),
            (std::vector<std::int32_t>{0, 1, 2}));
  EXPECT_EQ(vtp.array("CellData", "ReasonForTermination").values<std::int32_t>(),
            (std::vector<std::int32_t>{sampleReason(0), sampleReason(1), sampleReason(2)}));
  const auto points = vtp.array("Points", "Points").values<glm::vec3>();
  const auto times = vtp.array("PointData", "IntegrationTime").values<float>();
  const auto vectors = vtp.array("PointData", "velocity").values<glm::vec3>();
  const auto speeds = vtp.array("PointData", "Speed").values<float>();
  for (const std::uint32_t seed : {1u, 2u}) {
    SCOPED_TRACE(::testing::Message() << "seed " << seed);
    for (const std::size_t i : {2 * seed, 2 * seed + 1}) {
      EXPECT_EQ(points[i], samplePosition(seed, 0));
      EXPECT_EQ(times[i], sampleTime(seed, 0));
      EXPECT_EQ(vectors[i], sampleVector(seed, 0));
    }
    EXPECT_EQ(speeds[2 * seed], speeds[2 * seed + 1]);
  }
}

TEST_P(VtpWriter, EndpointsOnlyTracesAreEachAPointTwice) {
  const VtpFile vtp = writeAndRead(sampleTraces({1, 1, 1, 1}));
  EXPECT_EQ(vtp.piece.at("NumberOfPoints"), "8");
  EXPECT_EQ(vtp.array("Lines", "offsets").values<std::int64_t>(),
            (std::vector<std::int64_t>{2, 4, 6, 8}));
  EXPECT_EQ(vtp.array("Lines", "connectivity").values<std::int64_t>(),
            (std::vector<std::int64_t>{0, 1, 2, 3, 4, 5, 6, 7}));
}

// Many blocks of endpoints: a block may begin at a point's second copy, in any array.
TEST_P(VtpWriter, EndpointsOnlyTracesKeepEachPointTwiceAcrossBlocks) {
  const std::vector<std::uint32_t> counts(20000, 1);
  const VtpFile vtp = writeAndRead(sampleTraces(counts));
  const auto points = vtp.array("Points", "Points").values<glm::vec3>();
  const auto vectors = vtp.array("PointData", "velocity").values<glm::vec3>();
  const auto times = vtp.array("PointData", "IntegrationTime").values<float>();
  const auto speeds = vtp.array("PointData", "Speed").values<float>();
  ASSERT_EQ(points.size(), 2 * counts.size());
  ASSERT_EQ(vectors.size(), points.size());
  ASSERT_EQ(times.size(), points.size());
  ASSERT_EQ(speeds.size(), points.size());
  for (std::uint32_t seed = 0; seed < counts.size(); ++seed) {
    const glm::dvec3 v(sampleVector(seed, 0));
    const float speed = static_cast<float>(std::sqrt(glm::dot(v, v)));
    for (const std::size_t i : {2 * std::size_t(seed), 2 * std::size_t(seed) + 1}) {
      ASSERT_EQ(points[i], samplePosition(seed, 0)) << "written point " << i;
      ASSERT_EQ(vectors[i], sampleVector(seed, 0)) << "written point " << i;
      ASSERT_EQ(times[i], sampleTime(seed, 0)) << "written point " << i;
      ASSERT_FLOAT_EQ(speeds[i], speed) << "written point " << i;
    }
  }
}

// A trace without points has nothing to draw and no point to repeat; SeedIds names the others.
TEST_P(VtpWriter, ATraceWithoutPointsHasNoLineAndSeedIdsSkipIt) {
  const VtpFile vtp = writeAndRead(sampleTraces({2, 0, 3}));
  EXPECT_EQ(vtp.piece.at("NumberOfPoints"), "5");
  EXPECT_EQ(vtp.piece.at("NumberOfLines"), "2");
  EXPECT_EQ(vtp.array("Lines", "offsets").values<std::int64_t>(),
            (std::vector<std::int64_t>{2, 5}));
  EXPECT_EQ(vtp.array("CellData", "SeedIds").values<std::int32_t>(),
            (std::vector<std::int32_t>{0, 2}));
  EXPECT_EQ(vtp.array("CellData", "ReasonForTermination").values<std::int32_t>(),
            (std::vector<std::int32_t>{sampleReason(0), sampleReason(2)}));
  EXPECT_EQ(vtp.array("Points", "Points").values<glm::vec3>()[2], samplePosition(2, 0));
}

TEST_P(VtpWriter, TracesWithoutPointsAloneMakeAFileWithoutLines) {
  const VtpFile vtp = writeAndRead(sampleTraces({0, 0}));
  EXPECT_EQ(vtp.piece.at("NumberOfPoints"), "0");
  EXPECT_EQ(vtp.piece.at("NumberOfLines"), "0");
  for (const VtpArray& array : vtp.arrays) EXPECT_TRUE(array.bytes.empty()) << array.name();
}

TEST_P(VtpWriter, StreamsArraysLargerThanItsBuffer) {
  // 3000 traces of 1 to 100 points: ~150k points, several MiB per array group.
  std::vector<std::uint32_t> counts;
  for (std::uint32_t seed = 0; seed < 3000; ++seed) counts.push_back(1 + (seed * 37) % 100);
  const VtpFile vtp = writeAndRead(sampleTraces(counts));
  const auto points = vtp.array("Points", "Points").values<glm::vec3>();
  const auto speeds = vtp.array("PointData", "Speed").values<float>();
  const auto connectivity = vtp.array("Lines", "connectivity").values<std::int64_t>();
  const auto offsets = vtp.array("Lines", "offsets").values<std::int64_t>();
  ASSERT_EQ(offsets.size(), counts.size());
  std::size_t i = 0;
  for (std::uint32_t seed = 0; seed < counts.size(); ++seed) {
    for (std::uint32_t written = 0; written < writtenPoints(counts[seed]); ++written, ++i) {
      const std::uint32_t point = std::min(written, counts[seed] - 1);
      ASSERT_LT(i, points.size());
      ASSERT_EQ(points[i], samplePosition(seed, point)) << "seed " << seed << " point " << point;
      const glm::dvec3 v(sampleVector(seed, point));
      ASSERT_FLOAT_EQ(speeds[i], static_cast<float>(std::sqrt(glm::dot(v, v))));
      ASSERT_EQ(connectivity[i], static_cast<std::int64_t>(i));
    }
    ASSERT_EQ(offsets[seed], static_cast<std::int64_t>(i));
  }
  EXPECT_EQ(points.size(), i);
  EXPECT_EQ(vtp.piece.at("NumberOfPoints"), std::to_string(i));

  // Compressed, VTK's blocks: 32768 bytes each, the last one partial unless it is full.
  if (GetParam() == output::Compression::None) return;
  for (const VtpArray& array : vtp.arrays) {
    SCOPED_TRACE(array.name());
    const std::uint64_t bytes = array.bytes.size();
    ASSERT_EQ(array.blockHeader.size(), 3 + (bytes + 32767) / 32768);
    EXPECT_EQ(array.blockHeader[1], 32768u);
    EXPECT_EQ(array.blockHeader[2], bytes % 32768);
  }
}

TEST_P(VtpWriter, WritesFieldDataBeforeThePiece) {
  const std::vector<output::FieldDataArray> fieldData{
      output::textField("Input", "cloud <1> & \"2\".exa"),
      {"Names", std::vector<std::string>{"a", "", "b\xC3\xA9"}},
      output::numberField("StepSize", 0.25),
      {"Counts", std::vector<std::int64_t>{-1, 1LL << 40}},
  };
  const VtpFile vtp = writeAndRead(sampleTraces(kSamplePointCounts), fieldData);
  ASSERT_GE(vtp.arrays.size(), 4u);
  const auto text = [](const VtpArray& array) {
    return std::string(reinterpret_cast<const char*>(array.bytes.data()), array.bytes.size());
  };
  const VtpArray& input = vtp.arrays[0];
  EXPECT_EQ(input.section, "FieldData");
  EXPECT_EQ(input.attributes, (XmlAttributes{{"type", "String"},
                                             {"Name", "Input"},
                                             {"NumberOfTuples", "1"},
                                             {"format", "appended"},
                                             {"offset", input.attributes.at("offset")}}));
  EXPECT_EQ(text(input), std::string("cloud <1> & \"2\".exa\0", 20));
  EXPECT_EQ(text(vtp.array("FieldData", "Names")), std::string("a\0\0b\xC3\xA9\0", 7));
  EXPECT_EQ(vtp.array("FieldData", "Names").attributes.at("NumberOfTuples"), "3");
  EXPECT_EQ(vtp.array("FieldData", "StepSize").type(), "Float64");
  EXPECT_EQ(vtp.array("FieldData", "StepSize").values<double>(), std::vector<double>{0.25});
  EXPECT_EQ(vtp.array("FieldData", "Counts").type(), "Int64");
  EXPECT_EQ(vtp.array("FieldData", "Counts").values<std::int64_t>(),
            (std::vector<std::int64_t>{-1, 1LL << 40}));
  // The trace arrays follow, unchanged.
  EXPECT_EQ(vtp.array("Lines", "offsets").values<std::int64_t>(),
            (std::vector<std::int64_t>{3, 5, 10, 12}));
  const std::string file = readText(dir_ / "traces.vtp");
  EXPECT_LT(file.find("<FieldData>"), file.find("<Piece"));
}

TEST_P(VtpWriter, RefusesFieldDataItCannotWriteBeforeCreatingAFile) {
  const fs::path path = dir_ / "traces.vtp";
  output::VtpWriteOptions withNul = options();
  withNul.fieldData = {output::textField("Input", std::string("a\0b", 3))};
  EXPECT_THROW(output::writeVtp(path, sampleTraces(kSamplePointCounts), withNul),
               std::invalid_argument);
  output::VtpWriteOptions unnamed = options();
  unnamed.fieldData = {output::numberField("", 1.0)};
  EXPECT_THROW(output::writeVtp(path, sampleTraces(kSamplePointCounts), unnamed),
               std::invalid_argument);
  EXPECT_TRUE(entries().empty());
}

TEST_P(VtpWriter, ReplacesAnExistingFile) {
  const fs::path path = dir_ / "traces.vtp";
  std::ofstream(path) << "previous run";
  output::writeVtp(path, sampleTraces(kSamplePointCounts), options());
  EXPECT_EQ(readVtp(path).piece.at("NumberOfLines"), "4");
  EXPECT_EQ(entries(), std::set<std::string>{"traces.vtp"});
}

TEST_P(VtpWriter, CreatesTheFileWithTheUsualPermissions) {
  const mode_t mask = ::umask(0);
  ::umask(mask);
  const fs::path path = dir_ / "traces.vtp";
  output::writeVtp(path, sampleTraces(kSamplePointCounts), options());
  struct stat status {};
  ASSERT_EQ(::stat(path.c_str(), &status), 0);
  EXPECT_EQ(status.st_mode & 0777, 0666 & ~mask);
}

void expectErrorNames(const std::runtime_error& error, const fs::path& path, int osError) {
  const std::string what = error.what();
  EXPECT_NE(what.find(path.string()), std::string::npos) << what;
  EXPECT_NE(what.find(std::strerror(osError)), std::string::npos) << what;
}

TEST_P(VtpWriter, AMissingDirectoryThrowsNamingThePathAndReason) {
  const fs::path path = dir_ / "no-such-directory" / "traces.vtp";
  try {
    output::writeVtp(path, sampleTraces(kSamplePointCounts), options());
    FAIL() << "no exception";
  } catch (const std::runtime_error& error) {
    expectErrorNames(error, path, ENOENT);
  }
  EXPECT_TRUE(entries().empty());
}

TEST_P(VtpWriter, ATargetThatIsADirectoryThrowsAndLeavesNoTemporary) {
  const fs::path path = dir_ / "traces.vtp";
  fs::create_directory(path);
  try {
    output::writeVtp(path, sampleTraces(kSamplePointCounts), options());
    FAIL() << "no exception";
  } catch (const std::runtime_error& error) {
    expectErrorNames(error, path, EISDIR);
  }
  EXPECT_EQ(entries(), std::set<std::string>{"traces.vtp"});
  EXPECT_TRUE(fs::is_directory(path));
}

TEST_P(VtpWriter, AFailedWriteKeepsThePreviousFileAndLeavesNoTemporary) {
  const fs::path path = dir_ / "traces.vtp";
  std::ofstream(path) << "previous run";
  // A file size limit makes write() fail part way (EFBIG), as a full disk would (ENOSPC).
  const flow::TraceSet traces = sampleTraces(std::vector<std::uint32_t>(2000, 100));
  rlimit saved{};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &saved), 0);
  rlimit limited = saved;
  limited.rlim_cur = 64 * 1024;
  const auto savedHandler = ::signal(SIGXFSZ, SIG_IGN);
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &limited), 0);
  try {
    output::writeVtp(path, traces, options());
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error& error) {
    expectErrorNames(error, path, EFBIG);
  }
  ::setrlimit(RLIMIT_FSIZE, &saved);
  ::signal(SIGXFSZ, savedHandler);
  EXPECT_EQ(readText(path), "previous run");
  EXPECT_EQ(entries(), std::set<std::string>{"traces.vtp"});
}

TEST_P(VtpWriter, InconsistentTracesThrowBeforeCreatingAFile) {
  const fs::path path = dir_ / "traces.vtp";
  flow::TraceSet tooLong = sampleTraces(kSamplePointCounts);
  tooLong.offsets.back() += 1;  // one point more than the arrays hold
  EXPECT_THROW(output::writeVtp(path, tooLong), std::invalid_argument);

  flow::TraceSet backwards = sampleTraces(kSamplePointCounts);
  backwards.offsets[2] = backwards.offsets[3] + 1;
  EXPECT_THROW(output::writeVtp(path, backwards), std::invalid_argument);

  flow::TraceSet missingTimes = sampleTraces(kSamplePointCounts);
  missingTimes.times.pop_back();
  EXPECT_THROW(output::writeVtp(path, missingTimes), std::invalid_argument);

  flow::TraceSet missingReason = sampleTraces(kSamplePointCounts);
  missingReason.reasons.pop_back();
  EXPECT_THROW(output::writeVtp(path, missingReason), std::invalid_argument);
  EXPECT_TRUE(entries().empty());
}

TEST_P(VtpWriter, ANonFiniteValueIsRefusedAndNoFileIsMade) {
  const fs::path path = dir_ / "traces.vtp";
  flow::TraceSet badPosition = sampleTraces(kSamplePointCounts);
  badPosition.positions[4].y = std::numeric_limits<float>::infinity();
  try {
    output::writeVtp(path, badPosition, options());
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error& error) {
    EXPECT_THAT(error.what(), ::testing::HasSubstr("'Points' has a non-finite value (inf)"));
  }
  flow::TraceSet badTime = sampleTraces(kSamplePointCounts);
  badTime.times[7] = std::nanf("");
  EXPECT_THROW(output::writeVtp(path, badTime, options()), std::runtime_error);
  EXPECT_TRUE(entries().empty());
}

INSTANTIATE_TEST_SUITE_P(EveryCompression, VtpWriter, kEveryCompression, compressionTestName);

}  // namespace
}  // namespace amrstream::testing
