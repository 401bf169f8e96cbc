#pragma once
// The benchmark's outputs: a table on stdout (printed row by row as the runs finish) and one
// JSON document with everything (bench/plot_bench.py draws the plot from it).

#include <filesystem>
#include <string>

#include "bench_types.hpp"

namespace amrstream::bench {

std::string tableHeader();
std::string tableRow(const BenchRow& row);
std::string setupLine(const BackendSetup& setup);

// Written through a temporary file and a rename; throws std::system_error naming the path.
void writeJson(const std::filesystem::path& path, const BenchReport& report);

}  // namespace amrstream::bench
