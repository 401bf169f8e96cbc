#include "formats/hdf5_contiguous.hpp"

#include <fmt/format.h>

#include "amrstream/error.hpp"
#include "formats/hdf5_handle.hpp"

namespace amrstream::formats {

namespace {

bool storedInPlace(hid_t set) {
  const Hdf5Handle plist(H5Dget_create_plist(set), H5Pclose);
  return plist.valid() && H5Pget_layout(plist.get()) == H5D_CONTIGUOUS &&
         H5Pget_nfilters(plist.get()) == 0 && H5Pget_external_count(plist.get()) == 0;
}

// 4 or 8 for the machine's float or double, else 0.
int nativeFloatBytes(hid_t set) {
  const Hdf5Handle type(H5Dget_type(set), H5Tclose);
  if (!type.valid()) return 0;
  if (H5Tequal(type.get(), H5T_NATIVE_FLOAT) > 0) return 4;
  if (H5Tequal(type.get(), H5T_NATIVE_DOUBLE) > 0) return 8;
  return 0;
}

}  // namespace

std::optional<ContiguousFloats> contiguousFloats(hid_t set, const std::string& file,
                                                 const std::string& name, std::uint64_t count) {
  const int valueBytes = nativeFloatBytes(set);
  if (valueBytes == 0 || !storedInPlace(set)) return std::nullopt;
  const haddr_t offset = H5Dget_offset(set);
  if (offset == HADDR_UNDEF) return std::nullopt;  // never written: H5Dread gives the fill value
  const Hdf5Handle fileId(H5Iget_file_id(set), H5Fclose);
  hsize_t fileBytes = 0;
  if (!fileId.valid() || H5Fget_filesize(fileId.get(), &fileBytes) < 0)
    throw InputError(file, fmt::format("dataset '{}': cannot read the file size", name));
  const std::uint64_t bytes = count * std::uint64_t(valueBytes);
  if (offset > fileBytes || bytes > fileBytes - offset)
    throw InputError(file, fmt::format("dataset '{}': its {} values ({} bytes from byte {}) run "
                                       "past the end of the {}-byte file (truncated?)",
                                       name, count, bytes, offset, fileBytes));
  return ContiguousFloats{offset, valueBytes};
}

}  // namespace amrstream::formats
