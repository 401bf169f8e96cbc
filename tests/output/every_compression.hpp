#pragma once
// The parameters of tests run once per compression of the VTK XML writer, named after it:
//   INSTANTIATE_TEST_SUITE_P(EveryCompression, Suite, kEveryCompression, compressionTestName);

#include <gtest/gtest.h>

#include <string>

#include "output/vtk_compression.hpp"

namespace amrstream::testing {

inline const auto kEveryCompression = ::testing::Values(
    output::Compression::None, output::Compression::ZLib, output::Compression::LZ4);

inline std::string compressionTestName(const ::testing::TestParamInfo<output::Compression>& info) {
  return std::string(output::compressionName(info.param));
}

}  // namespace amrstream::testing
