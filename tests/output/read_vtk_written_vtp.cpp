// Reads the files rewrite_with_vtk.py wrote (VTK's vtkXMLPolyDataWriter re-encoding the sample
// write_sample_vtp wrote) with readVtpTraces and compares each with the sample TraceSet:
// `read_vtk_written_vtp DIR`. Prints one line per file; exits 1 when any differs.

#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

#include "amrstream/error.hpp"
#include "output/vtp_reader.hpp"
#include "sample_traces.hpp"

namespace {

using amrstream::flow::TraceSet;
using amrstream::testing::at;
using amrstream::testing::pointCountsOf;

// The first difference from `expected` over the valid points, or "" when there is none.
std::string difference(const TraceSet& read, const TraceSet& expected) {
  if (read.lineCount() != expected.lineCount()) {
    return std::to_string(read.lineCount()) + " traces, expected " +
           std::to_string(expected.lineCount());
  }
  const std::vector<std::uint32_t> counts = pointCountsOf(read);
  if (counts != pointCountsOf(expected)) return "point counts differ";
  if (read.reasons != expected.reasons) return "reasons differ";
  if (read.vectorName != expected.vectorName) return "vector name '" + read.vectorName + "'";
  for (std::uint32_t seed = 0; seed < read.lineCount(); ++seed) {
    if (read.steps[seed] != counts[seed] - 1) return "steps differ";
    for (std::uint32_t p = 0; p < counts[seed]; ++p) {
      const std::size_t r = at(read, seed, p), e = at(expected, seed, p);  // NOLINT
      const std::string where = " at trace " + std::to_string(seed) + " point " + std::to_string(p);
      if (read.positions[r] != expected.positions[e]) return "position" + where;
      if (read.times[r] != expected.times[e]) return "IntegrationTime" + where;
      if (read.vectors[r] != expected.vectors[e]) return "vector" + where;
    }
  }
  return "";
}

}  // namespace

int main(int argc, char** argv) {
  namespace fs = std::filesystem;
  using namespace amrstream;
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s DIR\n", argv[0]);
    return 2;
  }
  const fs::path dir = argv[1];
  const TraceSet expected = testing::sampleTraces(testing::kSamplePointCounts);
  int failures = 0;
  const auto report = [&](const fs::path& path, const std::string& problem) {
    std::printf("read_vtk_written_vtp: %s: %s\n", path.c_str(),
                problem.empty() ? "OK" : problem.c_str());
    failures += problem.empty() ? 0 : 1;
  };

  for (const char* name : {"appended_raw.vtp", "appended_raw_uint32.vtp", "appended_base64.vtp",
                           "binary.vtp", "ascii.vtp", "big_endian.vtp", "float64_int32.vtp",
                           "zlib_default.vtp", "zlib_raw.vtp", "zlib_binary.vtp", "lz4_raw.vtp"}) {
    const fs::path path = dir / name;
    try {
      report(path, difference(output::readVtpTraces(path), expected));
    } catch (const std::exception& e) {
      report(path, std::string("threw: ") + e.what());
    }
  }

  const fs::path lzma = dir / "lzma.vtp";
  try {
    output::readVtpTraces(lzma);
    report(lzma, "read an LZMA-compressed file without complaint");
  } catch (const InputError& e) {
    const std::string message = e.what();
    report(lzma,
           message.find(lzma.string()) != std::string::npos &&
                   message.find("vtkLZMADataCompressor, which is not read") != std::string::npos
               ? ""
               : "unexpected message: " + message);
  }
  return failures == 0 ? 0 : 1;
}
