#pragma once
// Whole-dataset HDF5 reads for tests that check a reader against the file independently.

#include <gtest/gtest.h>
#include <hdf5.h>

#include <vector>

namespace amrstream::testing {

// Every element of dataset `name` as `memoryType`; a failed open or read fails the test.
template <typename T>
std::vector<T> readWholeDataset(hid_t file, const char* name, hid_t memoryType) {
  const hid_t dataset = H5Dopen2(file, name, H5P_DEFAULT);
  EXPECT_GE(dataset, 0) << "cannot open dataset " << name;
  if (dataset < 0) return {};
  const hid_t space = H5Dget_space(dataset);
  std::vector<T> values(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
  EXPECT_GE(H5Dread(dataset, memoryType, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), 0)
      << "cannot read dataset " << name;
  H5Sclose(space);
  H5Dclose(dataset);
  return values;
}

}  // namespace amrstream::testing
