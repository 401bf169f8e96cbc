// Writes a known TraceSet for check_vtp_with_vtk.py: `write_sample_vtp OUT.vtp [--empty]`.
// The default set has 4 traces of 3, 1, 5 and 2 points and the vector "velocity"; the file holds
// lines of 3, 2, 5 and 2 points (12 points: the 1-point trace is written as its point twice).
// --empty writes a TraceSet with no seeds.

#include <cstdio>
#include <exception>
#include <string_view>

#include "output/vtp_writer.hpp"
#include "sample_traces.hpp"

int main(int argc, char** argv) {
  using namespace amrstream;
  const bool empty = argc == 3 && std::string_view(argv[2]) == "--empty";
  if (argc < 2 || argc > 3 || (argc == 3 && !empty)) {
    std::fprintf(stderr, "usage: %s OUT.vtp [--empty]\n", argv[0]);
    return 2;
  }
  try {
    const flow::TraceSet traces =
        empty ? testing::sampleTraces({})
              : testing::sampleTraces(testing::kSamplePointCounts);
    output::writeVtp(argv[1], traces);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "write_sample_vtp: %s\n", e.what());
    return 1;
  }
  return 0;
}
