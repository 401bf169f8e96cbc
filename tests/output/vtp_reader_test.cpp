#include "output/vtp_reader.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstring>
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
  const std::vector<std::uint32_t> readCounts = pointCountsOf(read);
  const std::vector<std::uint32_t> writtenCounts = pointCountsOf(written);
  for (std::uint32_t seed = 0; seed < read.lineCount(); ++seed) {
    EXPECT_EQ(read.steps[seed], readCounts[seed] - 1) << "seed " << seed;
    for (std::uint32_t p = 0; p < std::min(readCounts[seed], writtenCounts[seed]); ++p) {
      ASSERT_EQ(read.positions[at(read, seed, p)], written.positions[at(written, seed, p)])
          << "seed " << seed << " point " << p;
      ASSERT_EQ(read.times[at(read, seed, p)], written.times[at(written, seed, p)])
          << "seed " << seed << " point " << p;
      ASSERT_EQ(read.vectors[at(read, seed, p)], written.vectors[at(written, seed, p)])
          << "seed " << seed << " point " << p;
    }
  }
}

class VtpReader : public TempDirTest {
 protected:
  flow::TraceSet roundTrip(const flow::TraceSet& traces,
                           output::Compression compression = output::Compression::ZLib) {
    const fs::path path = dir_ / "traces.vtp";
    output::VtpWriteOptions options;
    options.compression = compression;
    output::writeVtp(path, traces, options);
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

TEST_F(VtpReader, ReadsTheFieldDataBackAndKnowsStreaklinesAges) {
  const fs::path path = dir_ / "streaklines.vtp";
  for (const output::Compression compression :
       {output::Compression::None, output::Compression::ZLib, output::Compression::LZ4}) {
    for (const std::string output : {"streaklines", "pathlines"}) {
      output::VtpWriteOptions options;
      options.compression = compression;
      options.fieldData = {output::textField("Output", output),
                           {"Empty", std::vector<std::string>{"a", "", "bc"}},
                           output::numberField("SimulationTime", 0.125),
                           output::integerField("Steps", -7)};
      output::writeVtp(path, sampleTraces(kSamplePointCounts), options);
      const output::VtpContents read = output::readVtpFile(path);
      EXPECT_EQ(read.lines.timesAreAges, output == "streaklines");
      ASSERT_EQ(read.fieldData.size(), 4u);
      EXPECT_EQ(read.fieldData[0].name, "Output");
      EXPECT_EQ(std::get<std::vector<std::string>>(read.fieldData[0].values),
                std::vector<std::string>{output});
      EXPECT_EQ(std::get<std::vector<std::string>>(read.fieldData[1].values),
                (std::vector<std::string>{"a", "", "bc"}));
      EXPECT_EQ(std::get<std::vector<double>>(read.fieldData[2].values),
                std::vector<double>{0.125});
      EXPECT_EQ(std::get<std::vector<std::int64_t>>(read.fieldData[3].values),
                std::vector<std::int64_t>{-7});
    }
  }
}

TEST_F(VtpReader, RoundTripsLinesOfDifferentLengths) {
  const flow::TraceSet written = sampleTraces({2, 3, 1});
  expectSameTraces(roundTrip(written), written);
}

TEST_F(VtpReader, RoundTripsEndpointsOnlyTraces) {
  const flow::TraceSet written = sampleTraces({1, 1, 1, 1, 1});
  expectSameTraces(roundTrip(written), written);
}

TEST_F(VtpReader, RoundTripsManyTracesInEveryCompression) {
  std::vector<std::uint32_t> counts;
  for (std::uint32_t seed = 0; seed < 5000; ++seed) counts.push_back(1 + (seed * 37) % 120);
  const flow::TraceSet written = sampleTraces(counts);
  for (const output::Compression compression :
       {output::Compression::None, output::Compression::ZLib, output::Compression::LZ4}) {
    SCOPED_TRACE(output::compressionName(compression));
    expectSameTraces(roundTrip(written, compression), written);
  }
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

// Ascii arrays are never compressed, even in a file that names a compressor.
TEST_F(VtpReader, ReadsEveryEncodingHeaderTypeByteOrderAndCompressor) {
  for (const TestEncoding encoding : {TestEncoding::AppendedRaw, TestEncoding::AppendedBase64,
                                      TestEncoding::Binary, TestEncoding::Ascii}) {
    for (const bool uint32Header : {false, true}) {
      for (const bool bigEndian : {false, true}) {
        for (const std::string compressor : {"", "zlib", "lz4"}) {
          SCOPED_TRACE(::testing::Message()
                       << "encoding " << int(encoding) << " UInt32 header " << uint32Header
                       << " big endian " << bigEndian << " compressor " << compressor);
          TestFileOptions options{encoding, uint32Header, bigEndian};
          options.compressor = compressor;
          expectTwoLines(read(twoLinePiece(), options));
        }
      }
    }
  }
}

// Other writers may cut blocks anywhere: values then straddle blocks (and the reader's batches).
TEST_F(VtpReader, ReadsCompressedBlocksOfAnySize) {
  for (const TestEncoding encoding :
       {TestEncoding::AppendedRaw, TestEncoding::AppendedBase64, TestEncoding::Binary}) {
    for (const std::uint64_t blockBytes : {1, 5, 7, 12, 1000}) {
      SCOPED_TRACE(::testing::Message()
                   << "encoding " << int(encoding) << " blocks of " << blockBytes);
      TestFileOptions options{encoding};
      options.compressor = "zlib";
      options.blockBytes = blockBytes;
      expectTwoLines(read(twoLinePiece(), options));
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
  EXPECT_THAT(message, HasSubstr(path.string() + ": no such file"));
}

TEST_F(VtpReader, ADirectoryNamesThePath) {
  const std::string message = inputErrorOf([&] { output::readVtpTraces(dir_); });
  EXPECT_THAT(message, HasSubstr(dir_.string() + ": is a directory"));
}

// Checked before opening: a FIFO without a writer would block, /dev/zero never end.
TEST_F(VtpReader, AFifoOrADeviceIsRefusedByName) {
  const fs::path fifo = dir_ / "fifo.vtp";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_THAT(inputErrorOf([&] { output::readVtpTraces(fifo); }),
              HasSubstr(fifo.string() + ": is a FIFO (named pipe), not a regular file"));
  EXPECT_THAT(inputErrorOf([&] { output::readVtpTraces("/dev/zero"); }),
              HasSubstr("/dev/zero: is a device, not a regular file"));
}

// A file whose size differs from what was read (here a /proc file, which says it is empty and is
// not) has changed underneath: refused by name before it is parsed.
TEST_F(VtpReader, AFileThatChangesWhileItIsReadFailsByName) {
  EXPECT_THAT(inputErrorOf([&] { output::readVtpTraces("/proc/self/status"); }),
              HasSubstr("/proc/self/status: the file changed while it was read: 0 bytes when "
                        "opened, more read"));
}

// A compressed array may claim a thousand times its compressed size: one whose values would not
// fit in the memory traces may take (3/4 of it; 8 bytes each once read as 64-bit integers) is
// refused before anything is allocated or decompressed. The blocks here are not even valid zlib.
TEST_F(VtpReader, RefusesACompressedArrayThatWouldNotFitInMemory) {
  const double memory = double(::sysconf(_SC_PHYS_PAGES)) * double(::sysconf(_SC_PAGE_SIZE));
  const std::uint64_t values = std::max<std::uint64_t>(3'000'000'000, 0.75 * memory / 8 + 1);
  const std::uint64_t compressed = values / 1032 + 1;  // what deflate could inflate that far
  const std::string header =
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\" "
      "byte_order=\"LittleEndian\" header_type=\"UInt64\" compressor=\"vtkZLibDataCompressor\">"
      "<PolyData><Piece NumberOfPoints=\"1\" NumberOfLines=\"1\"><Lines>"
      "<DataArray type=\"Int8\" Name=\"connectivity\" format=\"appended\" offset=\"0\"/>"
      "<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">" +
      std::to_string(values) +
      "</DataArray></Lines></Piece></PolyData><AppendedData encoding=\"raw\">_";
  std::string text = header;
  for (const std::uint64_t word : {std::uint64_t(1), values, std::uint64_t(0), compressed})
    text.append(reinterpret_cast<const char*>(&word), sizeof(word));  // one block of all values
  text.append(compressed, '\x55');
  text += "</AppendedData></VTKFile>\n";
  EXPECT_THAT(errorFor(text),
              HasSubstr("array Lines/connectivity holds " + std::to_string(values) + " values"));
}

// Expat handles an element's attributes in time linear in their number: 80,000 of them on
// <VTKFile> and <Piece> (2.4 MB of attributes) parse as any other file does.
TEST_F(VtpReader, ReadsElementsWithManyAttributes) {
  std::string attributes;
  for (int i = 0; i < 80000; ++i)
    attributes += " a" + std::to_string(i) + "=\"" + std::to_string(i) + "\"";
  std::string text = vtpText(twoLinePiece());
  text.insert(text.find("<Piece") + 6, attributes);
  text.insert(text.find("<VTKFile") + 8, attributes);
  expectTwoLines(output::readVtpTraces(write(text)));
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
              HasSubstr("the file ends inside <Lines> (truncated?)"));
  std::string mismatched = text;
  mismatched.replace(mismatched.find("</Lines>"), 8, "</Points>");
  EXPECT_THAT(errorFor(mismatched), HasSubstr("mismatched tag (the open element is <Lines>)"));
  std::string entity = text;
  entity.replace(entity.find("Name=\"velocity\""), 15, "Name=\"vel&oops;\"");
  EXPECT_THAT(errorFor(entity), HasSubstr("undefined entity"));
  std::string unquoted = text;
  unquoted.replace(unquoted.find("Name=\"velocity\""), 15, "Name=velocity");
  EXPECT_THAT(errorFor(unquoted), HasSubstr("malformed XML at line"));
  EXPECT_THAT(errorFor("<a><b>"), HasSubstr("the file ends inside <b>"));
  std::string deep;
  for (int i = 0; i < 100; ++i) deep += "<VTKFile>";
  EXPECT_THAT(errorFor(deep), HasSubstr("nested deeper than 64"));
}

// Entities could expand a small header into a huge one (the "billion laughs"); VTK uses none.
TEST_F(VtpReader, RefusesEntityDeclarations) {
  std::string text = vtpText(twoLinePiece());
  text.insert(text.find("<VTKFile"), "<!DOCTYPE VTKFile [<!ENTITY a \"aaaaaaaaaa\">]>\n");
  text.replace(text.find("Name=\"velocity\""), 15, "Name=\"&a;\"");
  EXPECT_THAT(errorFor(text), HasSubstr("the file declares an entity (a)"));
}

TEST_F(VtpReader, RejectsSeveralPiecesSayingSo) {
  TestFileOptions options;
  options.pieces = 2;
  EXPECT_THAT(errorFor(twoLinePiece(), options), HasSubstr("2 pieces"));
  options.pieces = 0;
  EXPECT_THAT(errorFor(twoLinePiece(), options), HasSubstr("no <Piece>"));
}

TEST_F(VtpReader, RejectsOtherCompressorsNamingTheOnesItReads) {
  std::string text = vtpText(twoLinePiece());
  text.insert(text.find("header_type"), "compressor=\"vtkLZMADataCompressor\" ");
  const std::string message = errorFor(text);
  EXPECT_THAT(message, HasSubstr("compressed with vtkLZMADataCompressor, which is not read"));
  EXPECT_THAT(message, HasSubstr("vtkZLibDataCompressor or vtkLZ4DataCompressor"));
}

// ---- corrupt compressed data ----

// A compressed file's text and the index where the block header of `array` starts.
struct CompressedText {
  std::string text;
  std::size_t header;
  std::size_t headerBytes;

  CompressedText(const std::string& compressor, const std::string& array, bool uint32Header = false)
      : headerBytes(uint32Header ? 4 : 8) {
    TestFileOptions options;
    options.compressor = compressor;
    options.uint32Header = uint32Header;
    text = vtpText(twoLinePiece(), options);
    header = appendedBlockStart(text, array);
  }
  // Overwrites header integer `index` (0: block count, 1: block size, 2: last block size,
  // 3 + i: compressed size of block i).
  void setHeader(std::size_t index, std::uint64_t value) {
    std::memcpy(text.data() + header + index * headerBytes, &value, headerBytes);
  }
  std::size_t firstBlock() const {
    std::uint64_t count = 0;
    std::memcpy(&count, text.data() + header, headerBytes);
    return header + (3 + count) * headerBytes;
  }
};

TEST_F(VtpReader, RejectsATruncatedCompressedBlock) {
  for (const std::string compressor : {"zlib", "lz4"}) {
    for (const TestEncoding encoding :
         {TestEncoding::AppendedRaw, TestEncoding::AppendedBase64, TestEncoding::Binary}) {
      SCOPED_TRACE(::testing::Message() << compressor << " encoding " << int(encoding));
      TestFileOptions options{encoding};
      options.compressor = compressor;
      const std::string text = vtpText(twoLinePiece(), options);
      // The file ends inside the last array's blocks; inline, the array's text ends early.
      const std::string cut =
          encoding == TestEncoding::Binary
              ? std::string(text).erase(text.rfind("\n        </DataArray>") - 6, 6)
              : text.substr(0, text.rfind("\n  </AppendedData>") - 6);
      const std::string message = errorFor(cut);
      EXPECT_THAT(message, HasSubstr("array Lines/offsets"));
      EXPECT_THAT(message, HasSubstr("truncated"));
    }
  }
}

TEST_F(VtpReader, RejectsBlockSizesThatNoStreamCouldInflateTo) {
  CompressedText huge("zlib", "Points");
  huge.setHeader(1, std::uint64_t(1) << 60);  // one full block of 2^60 bytes from a few bytes
  huge.setHeader(2, 0);
  EXPECT_THAT(errorFor(huge.text), HasSubstr("array Points: block 0 claims 1152921504606846976 "
                                             "bytes from"));
  EXPECT_THAT(errorFor(huge.text), HasSubstr("more than zlib can inflate to"));

  CompressedText hugeLast("lz4", "Points");
  hugeLast.setHeader(2, std::uint64_t(1) << 60);
  EXPECT_THAT(errorFor(hugeLast.text), HasSubstr("array Points: the last block "
                                                 "(1152921504606846976 bytes) is larger"));

  // 60 blocks (of 1 byte when written) declared 2^60 bytes each: the total overflows.
  TestFileOptions oneByteBlocks;
  oneByteBlocks.compressor = "zlib";
  oneByteBlocks.blockBytes = 1;
  std::string overflow = vtpText(twoLinePiece(), oneByteBlocks);
  const std::uint64_t blockBytes = std::uint64_t(1) << 60;
  std::memcpy(overflow.data() + appendedBlockStart(overflow, "Points") + 8, &blockBytes, 8);
  EXPECT_THAT(errorFor(overflow), HasSubstr("array Points: 60 blocks of 1152921504606846976 "
                                            "bytes overflow 64 bits"));
}

TEST_F(VtpReader, RejectsABlockCountThatDoesNotFitInTheFile) {
  for (const bool uint32Header : {false, true}) {
    SCOPED_TRACE(uint32Header);
    CompressedText text("zlib", "Points", uint32Header);
    text.setHeader(0, uint32Header ? 0xFFFFFFFFu : std::uint64_t(1) << 60);
    EXPECT_THAT(errorFor(text.text),
                HasSubstr(uint32Header ? "array Points: its block header declares 4294967295 "
                                         "compressed blocks, more than"
                                       : "array Points: its block header declares "
                                         "1152921504606846976 compressed blocks, more than"));
  }
  // Compressed sizes that add up to more than the file holds.
  CompressedText sizes("lz4", "Points");
  sizes.setHeader(3, std::uint64_t(1) << 40);
  EXPECT_THAT(errorFor(sizes.text),
              HasSubstr("array Points: the compressed blocks need 1099511627776 bytes"));
}

TEST_F(VtpReader, RejectsACorruptStream) {
  CompressedText corrupt("zlib", "Points");
  // Past the 2-byte zlib header: deflate data, and the Adler-32 check catches what it misses.
  for (std::size_t i = 2; i < 8; ++i) corrupt.text[corrupt.firstBlock() + i] ^= 0x5A;
  EXPECT_THAT(errorFor(corrupt.text),
              HasSubstr("array Points: block 0 is not a valid zlib stream of 60 bytes"));

  CompressedText garbage("lz4", "Points");
  for (std::size_t i = 0; i < 4; ++i) garbage.text[garbage.firstBlock() + i] = '\xFF';
  EXPECT_THAT(errorFor(garbage.text), HasSubstr("array Points: block 0 is not a valid lz4"));
}

TEST_F(VtpReader, RejectsBlocksThatInflateToAnotherSizeThanDeclared) {
  for (const std::string compressor : {"zlib", "lz4"}) {
    SCOPED_TRACE(compressor);
    // Points (60 bytes) in blocks of 32 and 28 bytes, declared as 36 and 24: the same total.
    TestFileOptions options;
    options.compressor = compressor;
    options.blockBytes = 32;
    std::string text = vtpText(twoLinePiece(), options);
    const std::size_t header = appendedBlockStart(text, "Points");
    const std::uint64_t declared[] = {36, 24};
    std::memcpy(text.data() + header + 8, declared, sizeof(declared));
    EXPECT_THAT(errorFor(text),
                HasSubstr("array Points: block 0 is not a valid " + compressor + " stream of 36"));
  }
}

TEST_F(VtpReader, RejectsACompressedArrayOfTheWrongLength) {
  TestPiece piece = twoLinePiece();
  setValues(piece, "IntegrationTime", {0, 0.5, 1, 0});
  TestFileOptions options;
  options.compressor = "zlib";
  EXPECT_THAT(errorFor(piece, options),
              HasSubstr("array PointData/IntegrationTime holds 4 values, expected 5 tuples of 1"));
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
