#include "output/vtp_reader.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

#include "input_error_of.hpp"
#include "output/vtp_writer.hpp"
#include "sample_traces.hpp"
#include "temp_dir_test.hpp"
#include "vtp_text.hpp"

namespace glm {
void PrintTo(const vec3& v, std::ostream* os) {
  *os << '(' << v.x << ", " << v.y << ", " << v.z << ')';
}
}  // namespace glm

namespace amrstream::testing {
namespace {

namespace fs = std::filesystem;

// Every point, count, step, reason and seed id equal.
void expectSameTraces(const flow::TraceSet& read, const flow::TraceSet& written) {
  ASSERT_EQ(read.lineCount(), written.lineCount());
  EXPECT_EQ(pointCountsOf(read), pointCountsOf(written));
  EXPECT_EQ(read.reasons, written.reasons);
  EXPECT_EQ(read.seedIds, written.seedIds);
  ASSERT_EQ(read.positions.size(), read.pointCount());
  ASSERT_EQ(read.times.size(), read.positions.size());
  ASSERT_EQ(read.vectors.size(), read.positions.size());
  ASSERT_EQ(read.steps.size(), read.lineCount());
  for (std::uint32_t seed = 0; seed < read.lineCount(); ++seed) {
    EXPECT_EQ(read.steps[seed], pointCountsOf(read)[seed] - 1) << "seed " << seed;
    for (std::uint32_t p = 0; p < std::min(pointCountsOf(read)[seed], pointCountsOf(written)[seed]);
         ++p) {
      SCOPED_TRACE(::testing::Message() << "seed " << seed << " point " << p);
      ASSERT_EQ(read.positions[at(read, seed, p)], written.positions[at(written, seed, p)]);
      ASSERT_EQ(read.times[at(read, seed, p)], written.times[at(written, seed, p)]);
      ASSERT_EQ(read.vectors[at(read, seed, p)], written.vectors[at(written, seed, p)]);
    }
  }
}

class VtpReader : public TempDirTest {
 protected:
  flow::TraceSet roundTrip(const flow::TraceSet& traces) {
    const fs::path path = dir_ / "traces.vtp";
    output::writeVtp(path, traces);
    return output::readVtpTraces(path);
  }

  fs::path write(const std::string& text, const std::string& name = "file.vtp") {
    const fs::path path = dir_ / name;
    std::ofstream(path, std::ios::binary) << text;
    return path;
  }

  flow::TraceSet read(const TestPiece& piece, const TestFileOptions& options = {}) {
    return output::readVtpTraces(write(vtpText(piece, options)));
  }

  // The message of the InputError reading `text` throws; fails unless it names the file.
  std::string errorFor(const std::string& text) {
    const fs::path path = write(text);
    const std::string message = inputErrorOf([&] { output::readVtpTraces(path); });
    EXPECT_NE(message.find(path.string()), std::string::npos) << message;
    return message;
  }
  std::string errorFor(const TestPiece& piece, const TestFileOptions& options = {}) {
    return errorFor(vtpText(piece, options));
  }
};

using ::testing::HasSubstr;

// ---- round trips through writeVtp ----

TEST_F(VtpReader, RoundTripsAnEmptyTraceSet) {
  const flow::TraceSet read = roundTrip(sampleTraces({}));
  EXPECT_EQ(read.lineCount(), 0u);
  EXPECT_TRUE(read.positions.empty());
  EXPECT_TRUE(pointCountsOf(read).empty());
  EXPECT_EQ(read.vectorName, "velocity");
}

TEST_F(VtpReader, RoundTripsOneTraceOfOnePoint) {
  const flow::TraceSet written = sampleTraces({1});
  const flow::TraceSet read = roundTrip(written);
  expectSameTraces(read, written);
  EXPECT_EQ(read.steps, std::vector<std::uint32_t>{0});
}

TEST_F(VtpReader, RoundTripsRaggedTraces) {
  const flow::TraceSet written = sampleTraces(kSamplePointCounts);
  const flow::TraceSet read = roundTrip(written);
  expectSameTraces(read, written);
  EXPECT_EQ(read.vectorName, "velocity");
  EXPECT_EQ(read.steps, (std::vector<std::uint32_t>{2, 0, 4, 1}));
}

TEST_F(VtpReader, RoundTripsLinesOfDifferentLengths) {
  const flow::TraceSet written = sampleTraces({2, 3, 1});
  expectSameTraces(roundTrip(written), written);
}

TEST_F(VtpReader, RoundTripsEndpointsOnlyTraces) {
  const flow::TraceSet written = sampleTraces({1, 1, 1, 1, 1});
  expectSameTraces(roundTrip(written), written);
}

TEST_F(VtpReader, RoundTripsManyTraces) {
  std::vector<std::uint32_t> counts;
  for (std::uint32_t seed = 0; seed < 5000; ++seed) counts.push_back(1 + (seed * 37) % 120);
  const flow::TraceSet written = sampleTraces(counts);
  expectSameTraces(roundTrip(written), written);
}

// The writer stores a 1-point trace as its point twice; a real step always advances the time.
TEST_F(VtpReader, KeepsATwoPointTraceThatStaysInPlaceButAdvancesInTime) {
  flow::TraceSet written = sampleTraces({2, 1});
  written.positions[at(written, 0, 1)] = written.positions[at(written, 0, 0)];
  const flow::TraceSet read = roundTrip(written);
  expectSameTraces(read, written);
  EXPECT_EQ(pointCountsOf(read), (std::vector<std::uint32_t>{2, 1}));
}

// The writer gives a trace without points no line (see vtp_writer.hpp), so it does not come back.
TEST_F(VtpReader, ATraceWithoutPointsDoesNotComeBack) {
  const flow::TraceSet read = roundTrip(sampleTraces({2, 0, 3}));
  ASSERT_EQ(read.lineCount(), 2u);
  EXPECT_EQ(pointCountsOf(read), (std::vector<std::uint32_t>{2, 3}));
  EXPECT_EQ(read.reasons, (std::vector<std::int32_t>{sampleReason(0), sampleReason(2)}));
  for (std::uint32_t p = 0; p < 3; ++p) {
    EXPECT_EQ(read.positions[at(read, 1, p)], samplePosition(2, p)) << "point " << p;
    EXPECT_EQ(read.times[at(read, 1, p)], sampleTime(2, p)) << "point " << p;
  }
}

TEST_F(VtpReader, ReadsTheVectorNameTheWriterChose) {
  EXPECT_EQ(roundTrip(sampleTraces({2}, "")).vectorName, "Vectors");
  EXPECT_EQ(roundTrip(sampleTraces({2}, "Speed")).vectorName, "Speed_vector");
  EXPECT_EQ(roundTrip(sampleTraces({2}, "u<v> & \"w\"")).vectorName, "u<v> & \"w\"");
}

// ---- other writers' layouts ----

// The trace set twoLinePiece() describes.
void expectTwoLines(const flow::TraceSet& traces) {
  ASSERT_EQ(traces.lineCount(), 2u);
  EXPECT_EQ(pointCountsOf(traces), (std::vector<std::uint32_t>{3, 2}));
  EXPECT_EQ(traces.steps, (std::vector<std::uint32_t>{2, 1}));
  EXPECT_EQ(traces.reasons, (std::vector<std::int32_t>{3, 7}));
  EXPECT_EQ(traces.vectorName, "velocity");
  EXPECT_EQ(traces.positions[at(traces, 0, 2)], glm::vec3(2, 0, 0));
  EXPECT_EQ(traces.positions[at(traces, 1, 0)], glm::vec3(5, 5, 5));
  EXPECT_EQ(traces.positions[at(traces, 1, 1)], glm::vec3(5, 6, 5));
  EXPECT_EQ(traces.times[at(traces, 0, 1)], 0.5f);
  EXPECT_EQ(traces.times[at(traces, 1, 1)], 0.25f);
  EXPECT_EQ(traces.vectors[at(traces, 0, 2)], glm::vec3(3, 0, 0));
  EXPECT_EQ(traces.vectors[at(traces, 1, 1)], glm::vec3(0, 2, 0));
}

TEST_F(VtpReader, ReadsEveryEncodingHeaderTypeAndByteOrder) {
  for (const TestEncoding encoding : {TestEncoding::AppendedRaw, TestEncoding::AppendedBase64,
                                      TestEncoding::Binary, TestEncoding::Ascii}) {
    for (const bool uint32Header : {false, true}) {
      for (const bool bigEndian : {false, true}) {
        SCOPED_TRACE(::testing::Message() << "encoding " << int(encoding) << " UInt32 header "
                                          << uint32Header << " big endian " << bigEndian);
        expectTwoLines(read(twoLinePiece(), {encoding, uint32Header, bigEndian}));
      }
    }
  }
}

TEST_F(VtpReader, ReadsOtherNumericTypes) {
  TestPiece piece = twoLinePiece();
  for (TestArray& a : piece.arrays) {
    if (a.section == "Points" || a.name == "IntegrationTime" || a.name == "velocity") {
      a.type = "Float64";
    }
    if (a.section == "Lines") a.type = "Int32";
    if (a.name == "ReasonForTermination") a.type = "UInt8";
  }
  expectTwoLines(read(piece));
  for (TestArray& a : piece.arrays) {
    if (a.section == "Lines") a.type = "UInt16";
  }
  expectTwoLines(read(piece));
}

TEST_F(VtpReader, GathersPointsThroughTheConnectivity) {
  TestPiece piece = twoLinePiece();
  setValues(piece, "connectivity", {4, 2, 0, 3, 1});
  const flow::TraceSet traces = read(piece);
  EXPECT_EQ(traces.positions[at(traces, 0, 0)], glm::vec3(5, 6, 5));
  EXPECT_EQ(traces.positions[at(traces, 0, 1)], glm::vec3(2, 0, 0));
  EXPECT_EQ(traces.times[at(traces, 0, 1)], 1.0f);
  EXPECT_EQ(traces.vectors[at(traces, 1, 1)], glm::vec3(2, 0, 0));
}

TEST_F(VtpReader, ReadsTheArrayThatVectorsNamesElseTheFirstFloatTriple) {
  TestPiece piece = twoLinePiece();
  piece.arrays.insert(piece.arrays.begin(),
                      {"PointData", "first", "Float64", 3, std::vector<double>(15, 9.0)});
  piece.arrays.insert(piece.arrays.begin(),
                      {"PointData", "ids", "Int32", 3, std::vector<double>(15, 1.0)});
  EXPECT_EQ(read(piece).vectorName, "velocity");

  piece.pointDataAttributes.clear();
  const flow::TraceSet traces = read(piece);
  EXPECT_EQ(traces.vectorName, "first");
  EXPECT_EQ(traces.vectors[at(traces, 1, 1)], glm::vec3(9.0f));
}

TEST_F(VtpReader, MissingArraysGiveZeros) {
  TestPiece piece = twoLinePiece();
  piece.pointDataAttributes.clear();
  std::erase_if(piece.arrays, [](const TestArray& a) {
    return a.section == "PointData" || a.section == "CellData";
  });
  const flow::TraceSet traces = read(piece);
  EXPECT_EQ(traces.vectorName, "");
  EXPECT_EQ(pointCountsOf(traces), (std::vector<std::uint32_t>{3, 2}));
  EXPECT_EQ(traces.reasons, (std::vector<std::int32_t>{0, 0}));
  for (std::size_t i = 0; i < traces.positions.size(); ++i) {
    EXPECT_EQ(traces.times[i], 0.0f);
    EXPECT_EQ(traces.vectors[i], glm::vec3(0.0f));
  }
}

TEST_F(VtpReader, WithoutTimesARepeatedPointIsStillOnePoint) {
  TestPiece piece = twoLinePiece();
  std::erase_if(piece.arrays, [](const TestArray& a) { return a.name == "IntegrationTime"; });
  setValues(piece, "connectivity", {0, 1, 2, 3, 3});
  EXPECT_EQ(pointCountsOf(read(piece)), (std::vector<std::uint32_t>{3, 1}));
}

TEST_F(VtpReader, SkipsVertexCellsAndTheirCellData) {
  TestPiece piece = twoLinePiece();
  piece.verts = 2;
  piece.arrays.push_back({"Verts", "connectivity", "Int64", 1, {0, 4}});
  piece.arrays.push_back({"Verts", "offsets", "Int64", 1, {1, 2}});
  setValues(piece, "ReasonForTermination", {100, 101, 3, 7});  // verts first, then lines
  expectTwoLines(read(piece));
}

TEST_F(VtpReader, AFileWithoutLinesIsAnEmptyTraceSet) {
  TestPiece piece = twoLinePiece();
  piece.lines = 0;
  piece.verts = 1;
  std::erase_if(piece.arrays, [](const TestArray& a) { return a.section == "Lines"; });
  piece.arrays.push_back({"Verts", "connectivity", "Int64", 1, {0}});
  piece.arrays.push_back({"Verts", "offsets", "Int64", 1, {1}});
  const flow::TraceSet traces = read(piece);
  EXPECT_EQ(traces.lineCount(), 0u);
  EXPECT_TRUE(traces.positions.empty());
}

TEST_F(VtpReader, AnEmptyLineIsATraceWithoutPoints) {
  TestPiece piece = twoLinePiece();
  piece.lines = 3;
  setValues(piece, "offsets", {3, 3, 5});
  setValues(piece, "ReasonForTermination", {3, 4, 7});
  const flow::TraceSet traces = read(piece);
  EXPECT_EQ(pointCountsOf(traces), (std::vector<std::uint32_t>{3, 0, 2}));
  EXPECT_EQ(traces.steps, (std::vector<std::uint32_t>{2, 0, 1}));
}

TEST_F(VtpReader, ToleratesCommentsDeclarationsAndAByteOrderMark) {
  std::string text = vtpText(twoLinePiece());
  text.insert(text.find("<VTKFile"), "<!-- made by <hand> -->\n<!DOCTYPE VTKFile>\n");
  text.insert(text.find("<PolyData>"), "<?pi x?><!-- <Piece> -->");
  expectTwoLines(output::readVtpTraces(write("\xEF\xBB\xBF" + text)));
}

// ---- bad input ----

TEST_F(VtpReader, AMissingFileNamesThePath) {
  const fs::path path = dir_ / "no-such.vtp";
  const std::string message = inputErrorOf([&] { output::readVtpTraces(path); });
  EXPECT_THAT(message, HasSubstr(path.string()));
  EXPECT_THAT(message, HasSubstr("cannot open"));
}

TEST_F(VtpReader, ADirectoryNamesThePath) {
  const std::string message = inputErrorOf([&] { output::readVtpTraces(dir_); });
  EXPECT_THAT(message, HasSubstr(dir_.string()));
  EXPECT_THAT(message, HasSubstr("cannot"));
}

TEST_F(VtpReader, RejectsFilesThatAreNotVtkPolyData) {
  EXPECT_THAT(errorFor(""), HasSubstr("empty"));
  EXPECT_THAT(errorFor("\x89PNG\r\n\x1a\n"), HasSubstr("not an XML file"));
  EXPECT_THAT(errorFor("<html><body/></html>"), HasSubstr("not a VTK XML file"));
  std::string grid = vtpText(twoLinePiece());
  grid.replace(grid.find("PolyData"), 8, "UnstructuredGrid");
  EXPECT_THAT(errorFor(grid), HasSubstr("\"UnstructuredGrid\" file, not PolyData"));
}

TEST_F(VtpReader, RejectsMalformedXml) {
  const std::string text = vtpText(twoLinePiece(), {TestEncoding::Ascii});
  EXPECT_THAT(errorFor(text.substr(0, text.size() / 2)), HasSubstr("truncated"));
  EXPECT_THAT(errorFor(text.substr(0, text.find("Name=\"offsets\"") + 7)),
              HasSubstr("unterminated attribute"));
  std::string mismatched = text;
  mismatched.replace(mismatched.find("</Lines>"), 8, "</Points>");
  EXPECT_THAT(errorFor(mismatched), HasSubstr("</Points> closes <Lines>"));
  std::string entity = text;
  entity.replace(entity.find("Name=\"velocity\""), 15, "Name=\"vel&oops;\"");
  EXPECT_THAT(errorFor(entity), HasSubstr("unknown entity"));
  EXPECT_THAT(errorFor("<a><b>"), HasSubstr("the file ends inside <b>"));
  std::string deep;
  for (int i = 0; i < 100; ++i) deep += "<VTKFile>";
  EXPECT_THAT(errorFor(deep), HasSubstr("nested deeper than 64"));
}

TEST_F(VtpReader, RejectsSeveralPiecesSayingSo) {
  TestFileOptions options;
  options.pieces = 2;
  EXPECT_THAT(errorFor(twoLinePiece(), options), HasSubstr("2 pieces"));
  options.pieces = 0;
  EXPECT_THAT(errorFor(twoLinePiece(), options), HasSubstr("no <Piece>"));
}

TEST_F(VtpReader, RejectsCompressedFilesSayingHowToWriteThem) {
  std::string text = vtpText(twoLinePiece());
  text.insert(text.find("header_type"), "compressor=\"vtkZLibDataCompressor\" ");
  const std::string message = errorFor(text);
  EXPECT_THAT(message, HasSubstr("compressed (vtkZLibDataCompressor)"));
  EXPECT_THAT(message, HasSubstr("SetCompressorTypeToNone"));
}

TEST_F(VtpReader, RejectsATruncatedAppendedBlock) {
  // The appended blocks end with the Lines arrays; cut into the last one.
  for (const TestEncoding encoding : {TestEncoding::AppendedRaw, TestEncoding::AppendedBase64}) {
    SCOPED_TRACE(int(encoding));
    const std::string text = vtpText(twoLinePiece(), {encoding});
    const std::size_t end = text.rfind("\n  </AppendedData>");
    EXPECT_THAT(errorFor(text.substr(0, end - 5)), HasSubstr("truncated"));
  }
  // A writer's own output cut short.
  const fs::path path = dir_ / "traces.vtp";
  output::writeVtp(path, sampleTraces(kSamplePointCounts));
  fs::resize_file(path, fs::file_size(path) - 40);
  const std::string message = inputErrorOf([&] { output::readVtpTraces(path); });
  EXPECT_THAT(message, HasSubstr(path.string()));
  EXPECT_THAT(message, HasSubstr("truncated"));
}

TEST_F(VtpReader, RejectsAnOffsetOutsideTheAppendedData) {
  std::string text = vtpText(twoLinePiece());
  const std::size_t at = text.find("offset=\"", text.find("Name=\"Points\"")) + 8;
  text.replace(at, text.find('"', at) - at, "123456789");
  EXPECT_THAT(errorFor(text), HasSubstr("offset 123456789, outside the appended data"));
}

TEST_F(VtpReader, RejectsConnectivityOutOfRange) {
  TestPiece piece = twoLinePiece();
  setValues(piece, "connectivity", {0, 1, 2, 3, 5});
  EXPECT_THAT(errorFor(piece), HasSubstr("Lines/connectivity[4] = 5 is not a point id"));
  setValues(piece, "connectivity", {0, -1, 2, 3, 4});
  EXPECT_THAT(errorFor(piece), HasSubstr("Lines/connectivity[1] = -1"));
  setValues(piece, "connectivity", {0, 1, 2, 3});
  EXPECT_THAT(errorFor(piece), HasSubstr("offsets end at 5 but Lines/connectivity holds 4"));
}

TEST_F(VtpReader, RejectsDecreasingOffsets) {
  TestPiece piece = twoLinePiece();
  piece.lines = 3;
  setValues(piece, "offsets", {3, 2, 5});
  setValues(piece, "ReasonForTermination", {1, 2, 3});
  EXPECT_THAT(errorFor(piece), HasSubstr("offsets decrease at line 1"));
  setValues(piece, "offsets", {-1, 2, 5});
  EXPECT_THAT(errorFor(piece), HasSubstr("offsets[0] is -1"));
}

TEST_F(VtpReader, RejectsNonFinitePositions) {
  TestPiece piece = twoLinePiece();
  auto points = arrayNamed(piece, "Points").values;
  points[4] = std::numeric_limits<double>::quiet_NaN();
  setValues(piece, "Points", points);
  EXPECT_THAT(errorFor(piece), HasSubstr("point 1 has a non-finite position"));
  points[4] = std::numeric_limits<double>::infinity();
  setValues(piece, "Points", points);
  EXPECT_THAT(errorFor(piece, {TestEncoding::Binary}), HasSubstr("point 1 has a non-finite"));
  // A Float64 coordinate beyond float's range.
  arrayNamed(piece, "Points").type = "Float64";
  points[4] = 1e300;
  setValues(piece, "Points", points);
  EXPECT_THAT(errorFor(piece), HasSubstr("point 1 has a non-finite position"));
}

TEST_F(VtpReader, RejectsArraysOfTheWrongShape) {
  TestPiece piece = twoLinePiece();
  arrayNamed(piece, "Points").components = 2;
  EXPECT_THAT(errorFor(piece), HasSubstr("array Points has 2 components, expected 3"));

  piece = twoLinePiece();
  arrayNamed(piece, "Points").values.pop_back();
  EXPECT_THAT(errorFor(piece), HasSubstr("array Points holds"));

  piece = twoLinePiece();
  arrayNamed(piece, "IntegrationTime").components = 3;
  EXPECT_THAT(errorFor(piece), HasSubstr("IntegrationTime has 3 components, expected 1"));

  piece = twoLinePiece();
  setValues(piece, "ReasonForTermination", {1});
  EXPECT_THAT(errorFor(piece), HasSubstr("CellData/ReasonForTermination holds 1"));

  piece = twoLinePiece();
  piece.pointDataAttributes = R"(Vectors="missing")";
  EXPECT_THAT(errorFor(piece), HasSubstr("Vectors=\"missing\"> names no point array"));

  piece = twoLinePiece();
  std::erase_if(piece.arrays, [](const TestArray& a) { return a.name == "offsets"; });
  EXPECT_THAT(errorFor(piece), HasSubstr("<Lines> has no \"offsets\" array"));
}

TEST_F(VtpReader, RejectsBadValuesInEachEncoding) {
  std::string ascii = vtpText(twoLinePiece(), {TestEncoding::Ascii});
  const std::size_t ids = ascii.find('\n', ascii.find("Name=\"connectivity\"")) + 1;
  ascii.replace(ascii.find("0 1 2 3 4", ids), 9, "0 1.5 2 3 4");
  EXPECT_THAT(errorFor(ascii), HasSubstr("value 1 (\"1.5\") is not a valid Int64 value"));
  ascii.replace(ascii.find("0 1.5 2 3 4", ids), 11, "0 one 2 3 4");
  EXPECT_THAT(errorFor(ascii), HasSubstr("value 1 (\"one\") is not a valid Int64 value"));

  TestPiece floatIds = twoLinePiece();
  arrayNamed(floatIds, "connectivity").type = "Float32";
  setValues(floatIds, "connectivity", {0, 1, 2, 3, 3.5});
  EXPECT_THAT(errorFor(floatIds), HasSubstr("value 4 (3.5) is not a whole number"));

  std::string binary = vtpText(twoLinePiece(), {TestEncoding::Binary});
  const std::size_t data = binary.find('\n', binary.find("Name=\"offsets\"")) + 11;
  binary[data + 2] = '*';
  EXPECT_THAT(errorFor(binary), HasSubstr("array Lines/offsets is not valid base64"));

  std::string format = vtpText(twoLinePiece());
  format.replace(format.find("format=\"appended\""), 17, "format=\"hex\"");
  EXPECT_THAT(errorFor(format),
              HasSubstr("format \"hex\"; appended, binary and ascii are supported"));

  std::string count = vtpText(twoLinePiece());
  count.replace(count.find("NumberOfPoints=\"5\""), 18, "NumberOfPoints=\"five\"");
  EXPECT_THAT(errorFor(count), HasSubstr("NumberOfPoints=\"five\" is not a count"));
}

}  // namespace
}  // namespace amrstream::testing
