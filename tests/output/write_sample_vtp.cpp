// Writes a known TraceSet for check_vtp_with_vtk.py:
// `write_sample_vtp OUT.vtp [--empty] [--compression none|zlib|lz4]` (writeVtp's default: zlib).
// The default set has 4 traces of 3, 1, 5 and 2 points and the vector "velocity"; the file holds
// lines of 3, 2, 5 and 2 points (12 points: the 1-point trace is written as its point twice).
// --empty writes a TraceSet with no seeds.

#include <cstdio>
#include <exception>
#include <optional>
#include <string_view>

#include "output/vtp_writer.hpp"
#include "sample_traces.hpp"

int main(int argc, char** argv) {
  using namespace amrstream;
  bool empty = false;
  output::VtpWriteOptions options;
  bool usage = argc < 2;
  for (int i = 2; i < argc && !usage; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--empty") {
      empty = true;
    } else if (arg == "--compression" && i + 1 < argc) {
      const std::optional<output::Compression> compression = output::compressionNamed(argv[++i]);
      usage = !compression;
      if (compression) options.compression = *compression;
    } else {
      usage = true;
    }
  }
  if (usage) {
    std::fprintf(stderr, "usage: %s OUT.vtp [--empty] [--compression none|zlib|lz4]\n", argv[0]);
    return 2;
  }
  try {
    const flow::TraceSet traces =
        empty ? testing::sampleTraces({})
              : testing::sampleTraces(testing::kSamplePointCounts);
    output::writeVtp(argv[1], traces, options);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "write_sample_vtp: %s\n", e.what());
    return 1;
  }
  return 0;
}
