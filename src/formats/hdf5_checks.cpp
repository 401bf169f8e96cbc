#include "formats/hdf5_checks.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <limits>

#include "amrstream/error.hpp"
#include "formats/hdf5_handle.hpp"
#include "util/input_file.hpp"

namespace amrstream::formats {

namespace {

[[noreturn]] void fail(const std::string& file, const std::string& name,
                       const std::string& problem) {
  throw InputError(file, fmt::format("dataset '{}': {}", name, problem));
}

std::vector<hsize_t> declaredShape(hid_t set, const std::string& file, const std::string& name) {
  const Hdf5Handle space(H5Dget_space(set), H5Sclose);
  if (!space.valid()) fail(file, name, "cannot read the dataspace");
  const int rank = H5Sget_simple_extent_ndims(space.get());
  if (rank < 0 || rank > H5S_MAX_RANK) fail(file, name, "cannot read the dataspace");
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  if (rank > 0 && H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr) < 0)
    fail(file, name, "cannot read the dataspace");
  return dims;
}

// Sets `floatBytes` and `bigEndian` for IEEE float32 and float64 of either byte order.
void ieeeFloat(hid_t type, StoredDataset& facts) {
  if (H5Tequal(type, H5T_IEEE_F32LE) > 0) facts.floatBytes = 4;
  if (H5Tequal(type, H5T_IEEE_F64LE) > 0) facts.floatBytes = 8;
  if (H5Tequal(type, H5T_IEEE_F32BE) > 0) facts.floatBytes = 4, facts.bigEndian = true;
  if (H5Tequal(type, H5T_IEEE_F64BE) > 0) facts.floatBytes = 8, facts.bigEndian = true;
}

}  // namespace

std::uint64_t checkedValueCount(const std::vector<hsize_t>& shape, std::uint64_t elementBytes,
                                bool filtered, std::uint64_t storedBytes, std::uint64_t fileBytes,
                                const std::string& file, const std::string& name) {
  std::uint64_t count = 1;
  for (hsize_t d : shape) count = checkedProduct(count, d, file, "dataset '" + name + "' shape");
  if (count > kMaxDatasetValues)
    fail(file, name,
         fmt::format("declares {} values, more than the {} accepted", count, kMaxDatasetValues));
  if (elementBytes == 0) fail(file, name, "cannot read the datatype");
  const std::uint64_t needed = checkedProduct(count, elementBytes, file, "dataset '" + name + "'");
  const std::uint64_t least = filtered ? needed / kMaxCompressionRatio : needed;
  if (storedBytes < least)
    fail(file, name,
         fmt::format("declares {} values of {} bytes ({} bytes) but the file stores {} bytes "
                     "for them{}",
                     count, elementBytes, needed, storedBytes,
                     filtered ? " (too few even compressed)" : ""));
  if (storedBytes > fileBytes)
    fail(file, name,
         fmt::format("claims {} bytes of storage in a file of {} bytes (truncated?)", storedBytes,
                     fileBytes));
  return count;
}

StoredDataset inspectStoredDataset(hid_t set, const std::string& file, const std::string& name) {
  StoredDataset facts;
  facts.shape = declaredShape(set, file, name);
  const Hdf5Handle type(H5Dget_type(set), H5Tclose);
  const std::size_t elementBytes = type.valid() ? H5Tget_size(type.get()) : 0;
  const Hdf5Handle plist(H5Dget_create_plist(set), H5Pclose);
  const int filters = plist.valid() ? H5Pget_nfilters(plist.get()) : -1;
  if (filters < 0) fail(file, name, "cannot read the creation properties");
  const Hdf5Handle fileId(H5Iget_file_id(set), H5Fclose);
  hsize_t fileBytes = 0;
  if (!fileId.valid() || H5Fget_filesize(fileId.get(), &fileBytes) < 0)
    fail(file, name, "cannot read the file size");
  facts.count = checkedValueCount(facts.shape, elementBytes, filters != 0, H5Dget_storage_size(set),
                                  fileBytes, file, name);
  facts.typeClass = H5Tget_class(type.get());
  if (facts.typeClass == H5T_FLOAT) ieeeFloat(type.get(), facts);
  facts.inPlace = H5Pget_layout(plist.get()) == H5D_CONTIGUOUS && filters == 0 &&
                  H5Pget_external_count(plist.get()) == 0;
  facts.fileBytes = fileBytes;
  facts.offset = H5Dget_offset(set);
  return facts;
}

std::uint64_t requireStoredValues(hid_t set, const std::string& file, const std::string& name) {
  return inspectStoredDataset(set, file, name).count;
}

std::optional<std::vector<std::string>> readHdf5Strings(hid_t set, hid_t stringType,
                                                        const char* member, std::uint64_t count) {
  const htri_t variable = H5Tis_variable_str(stringType);
  const std::size_t width = H5Tget_size(stringType);
  const H5T_cset_t cset = H5Tget_cset(stringType);
  if (variable < 0 || width == 0 || cset < 0) return std::nullopt;
  // Null padding in memory: HDF5 then keeps every character of a fixed-length string, where a
  // null-terminated memory type of the same width would drop the last to make room for a NUL.
  const Hdf5Handle text(H5Tcopy(H5T_C_S1), H5Tclose);
  if (!text.valid() || H5Tset_cset(text.get(), cset) < 0) return std::nullopt;
  const std::size_t elementBytes = variable > 0 ? sizeof(char*) : width;
  const bool typed = variable > 0 ? H5Tset_size(text.get(), H5T_VARIABLE) >= 0
                                  : H5Tset_size(text.get(), width) >= 0 &&
                                        H5Tset_strpad(text.get(), H5T_STR_NULLPAD) >= 0;
  if (!typed) return std::nullopt;
  Hdf5Handle wrapped;
  hid_t memoryType = text.get();
  if (member != nullptr) {
    wrapped = Hdf5Handle(H5Tcreate(H5T_COMPOUND, elementBytes), H5Tclose);
    if (!wrapped.valid() || H5Tinsert(wrapped.get(), member, 0, text.get()) < 0)
      return std::nullopt;
    memoryType = wrapped.get();
  }
  std::vector<char> buffer(count * elementBytes + 1, '\0');
  if (count > 0 && H5Dread(set, memoryType, H5S_ALL, H5S_ALL, H5P_DEFAULT, buffer.data()) < 0)
    return std::nullopt;
  std::vector<std::string> strings;
  strings.reserve(count);
  for (std::uint64_t i = 0; i < count; ++i) {
    const char* element = buffer.data() + i * elementBytes;
    if (variable > 0) {
      const char* pointer = nullptr;
      std::memcpy(&pointer, element, sizeof pointer);
      strings.emplace_back(pointer == nullptr ? "" : pointer);
    } else {
      strings.emplace_back(element, std::find(element, element + width, '\0'));
    }
  }
  if (variable > 0 && count > 0) {
    const Hdf5Handle space(H5Dget_space(set), H5Sclose);
    if (!space.valid() || H5Dvlen_reclaim(memoryType, space.get(), H5P_DEFAULT, buffer.data()) < 0)
      return std::nullopt;
  }
  return strings;
}

}  // namespace amrstream::formats
