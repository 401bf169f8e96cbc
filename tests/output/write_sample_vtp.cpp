// Writes a known TraceSet for check_vtp_with_vtk.py:
// `write_sample_vtp OUT.vtp [--empty] [--precise] [--compression none|zlib|lz4]` (writeVtp's
// default: zlib). The default set has 4 traces of 3, 1, 5 and 2 points and the vector "velocity";
// the file holds lines of 3, 2, 5 and 2 points (12 points: the 1-point trace is written as its
// point twice). --empty writes a TraceSet with no seeds. --precise gives the traces precise
// positions (Float64 Points) and also writes the points the file should hold, one "x y z" line
// each with every digit of the doubles, to OUT.vtp.points.

#include <algorithm>
#include <cstdio>
#include <exception>
#include <fstream>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "output/vtp_writer.hpp"
#include "sample_traces.hpp"

namespace {

// The points of the file, with 17 significant digits (exact for doubles).
void writeExpectedPoints(const std::string& path, const amrstream::flow::TraceSet& traces) {
  std::ofstream out(path);
  out.precision(17);
  for (std::size_t line = 0; line < traces.lineCount(); ++line) {
    const std::uint64_t first = traces.firstPoint(line), count = traces.pointCount(line);
    const std::uint64_t written = count == 1 ? 2 : count;  // a 1-point trace's point twice
    for (std::uint64_t p = 0; p < written; ++p) {
      const glm::dvec3 position =
          amrstream::testing::exactPosition(traces, first + std::min(p, count - 1));
      out << position.x << ' ' << position.y << ' ' << position.z << '\n';
    }
  }
  if (!out.flush()) throw std::runtime_error("cannot write " + path);
}

}  // namespace

int main(int argc, char** argv) {
  using namespace amrstream;
  bool empty = false;
  bool precise = false;
  output::VtpWriteOptions options;
  bool usage = argc < 2;
  for (int i = 2; i < argc && !usage; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--empty") {
      empty = true;
    } else if (arg == "--precise") {
      precise = true;
    } else if (arg == "--compression" && i + 1 < argc) {
      const std::optional<output::Compression> compression = output::compressionNamed(argv[++i]);
      usage = !compression;
      if (compression) options.compression = *compression;
    } else {
      usage = true;
    }
  }
  if (usage) {
    std::fprintf(stderr, "usage: %s OUT.vtp [--empty] [--precise] [--compression none|zlib|lz4]\n",
                 argv[0]);
    return 2;
  }
  try {
    const std::vector<std::uint32_t> counts =
        empty ? std::vector<std::uint32_t>{} : testing::kSamplePointCounts;
    const flow::TraceSet traces =
        precise ? testing::preciseSampleTraces(counts) : testing::sampleTraces(counts);
    output::writeVtp(argv[1], traces, options);
    if (precise) writeExpectedPoints(std::string(argv[1]) + ".points", traces);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "write_sample_vtp: %s\n", e.what());
    return 1;
  }
  return 0;
}
