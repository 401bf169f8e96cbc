#include "formats/hdf5_writing.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <type_traits>

#include "amrstream/error.hpp"

namespace amrstream::formats {

namespace {

constexpr std::size_t kNameWidth = 80;

Hdf5Handle fixedString(std::size_t width) {
  Hdf5Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  if (type.valid()) {
    H5Tset_size(type.get(), std::max<std::size_t>(width, 1));
    H5Tset_strpad(type.get(), H5T_STR_NULLPAD);
  }
  return type;
}

void copyText(char* into, const std::string& text, std::size_t width) {
  std::memset(into, 0, width);
  std::memcpy(into, text.data(), std::min(width, text.size()));
}

}  // namespace

Hdf5Writing::Hdf5Writing(const std::filesystem::path& path, std::string name)
    : name_(std::move(name)) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  file_ = Hdf5Handle(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
  if (!file_.valid()) throw InputError(name_, "cannot create the HDF5 file");
}

void Hdf5Writing::fail(const std::string& dataset) const {
  throw InputError(name_, fmt::format("cannot write dataset '{}' (disk full?)", dataset));
}

Hdf5Handle Hdf5Writing::group(const std::string& name) const {
  Hdf5Handle group(H5Gcreate2(file_.get(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                   H5Gclose);
  if (!group.valid()) fail(name);
  return group;
}

void Hdf5Writing::dataset(hid_t where, const std::string& name, hid_t type, hid_t space,
                          hid_t memType, const void* values) const {
  const Hdf5Handle set(
      H5Dcreate2(where, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
      H5Dclose);
  if (!set.valid() || H5Dwrite(set.get(), memType, H5S_ALL, H5S_ALL, H5P_DEFAULT, values) < 0)
    fail(name);
}

void Hdf5Writing::array(hid_t where, const std::string& name, std::span<const hsize_t> dims,
                        hid_t memType, hid_t fileType, const void* values) const {
  const Hdf5Handle space(H5Screate_simple(int(dims.size()), dims.data(), nullptr), H5Sclose);
  if (!space.valid()) fail(name);
  dataset(where, name, fileType, space.get(), memType, values);
}

void Hdf5Writing::strings(const std::string& name, const std::vector<std::string>& values) const {
  std::size_t width = 1;
  for (const std::string& s : values) width = std::max(width, s.size());
  std::vector<char> bytes(values.size() * width);
  for (std::size_t i = 0; i < values.size(); ++i) copyText(&bytes[i * width], values[i], width);
  const Hdf5Handle type = fixedString(width);
  const hsize_t dims[] = {values.size(), 1};
  const Hdf5Handle space(H5Screate_simple(2, dims, nullptr), H5Sclose);
  if (!type.valid() || !space.valid()) fail(name);
  dataset(root(), name, type.get(), space.get(), type.get(), bytes.data());
}

template <typename T>
void Hdf5Writing::pairs(const std::string& name,
                        const std::vector<std::pair<std::string, T>>& values) const {
  const bool text = std::is_same_v<T, std::string>;
  const std::size_t valueBytes = text ? kNameWidth : sizeof(T);
  const std::size_t recordBytes = kNameWidth + valueBytes;
  const Hdf5Handle nameType = fixedString(kNameWidth);
  Hdf5Handle valueType;
  if constexpr (std::is_same_v<T, std::string>)
    valueType = fixedString(kNameWidth);
  else
    valueType =
        Hdf5Handle(H5Tcopy(std::is_same_v<T, int> ? H5T_NATIVE_INT : H5T_NATIVE_DOUBLE), H5Tclose);
  const Hdf5Handle record(H5Tcreate(H5T_COMPOUND, recordBytes), H5Tclose);
  if (!nameType.valid() || !valueType.valid() || !record.valid() ||
      H5Tinsert(record.get(), "name", 0, nameType.get()) < 0 ||
      H5Tinsert(record.get(), "value", kNameWidth, valueType.get()) < 0)
    fail(name);
  std::vector<char> bytes(values.size() * recordBytes);
  for (std::size_t i = 0; i < values.size(); ++i) {
    char* at = &bytes[i * recordBytes];
    copyText(at, values[i].first, kNameWidth);
    if constexpr (std::is_same_v<T, std::string>)
      copyText(at + kNameWidth, values[i].second, kNameWidth);
    else
      std::memcpy(at + kNameWidth, &values[i].second, sizeof(T));
  }
  const hsize_t count = values.size();
  const Hdf5Handle space(H5Screate_simple(1, &count, nullptr), H5Sclose);
  if (!space.valid()) fail(name);
  dataset(root(), name, record.get(), space.get(), record.get(), bytes.data());
}

template void Hdf5Writing::pairs(const std::string&,
                                 const std::vector<std::pair<std::string, int>>&) const;
template void Hdf5Writing::pairs(const std::string&,
                                 const std::vector<std::pair<std::string, double>>&) const;
template void Hdf5Writing::pairs(const std::string&,
                                 const std::vector<std::pair<std::string, std::string>>&) const;

void Hdf5Writing::close() {
  if (H5Fflush(file_.get(), H5F_SCOPE_GLOBAL) < 0) throw InputError(name_, "cannot write it");
  file_ = Hdf5Handle();  // closes
}

}  // namespace amrstream::formats
