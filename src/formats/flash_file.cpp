#include "flash_file.hpp"

#include <algorithm>
#include <cstring>

#include "util/input_error.hpp"

namespace amrstream::formats::flash {

namespace {

std::string trimmedText(const char* text, std::size_t width) {
  std::string s(text, width);
  s.erase(std::find(s.begin(), s.end(), '\0'), s.end());
  s.erase(s.find_last_not_of(' ') + 1);
  return s;
}

}  // namespace

FlashFile::FlashFile(const std::filesystem::path& path) : path_(path.string()) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) fail("no such file");
  if (H5Fis_hdf5(path_.c_str()) <= 0) fail("not an HDF5 file (or truncated)");
  file_ = Handle(H5Fopen(path_.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (!file_.valid()) fail("cannot open the HDF5 file (truncated or corrupt?)");
}

void FlashFile::fail(const std::string& problem) const { throw InputError(path_, problem); }

void FlashFile::fail(const std::string& dataset, const std::string& problem) const {
  throw InputError(path_, fmt::format("dataset '{}': {}", dataset, problem));
}

bool FlashFile::has(const std::string& name) const {
  return H5Lexists(file_.get(), name.c_str(), H5P_DEFAULT) > 0;
}

Handle FlashFile::open(const std::string& name, const std::string& why) const {
  if (!has(name)) fail(name, "missing" + why);
  Handle set(H5Dopen2(file_.get(), name.c_str(), H5P_DEFAULT), H5Dclose);
  if (!set.valid()) fail(name, "cannot open");
  return set;
}

std::vector<hsize_t> FlashFile::dims(const std::string& name, const Handle& set) const {
  Handle space(H5Dget_space(set.get()), H5Sclose);
  if (!space.valid()) fail(name, "cannot read the dataspace");
  const int rank = H5Sget_simple_extent_ndims(space.get());
  if (rank < 0) fail(name, "cannot read the dataspace");
  std::vector<hsize_t> result(static_cast<std::size_t>(rank));
  if (rank > 0 && H5Sget_simple_extent_dims(space.get(), result.data(), nullptr) < 0)
    fail(name, "cannot read the dataspace");
  return result;
}

H5T_class_t FlashFile::typeClass(const std::string& name, const Handle& set,
                                 std::size_t* size) const {
  Handle type(H5Dget_type(set.get()), H5Tclose);
  if (!type.valid()) fail(name, "cannot read the datatype");
  if (size != nullptr) *size = H5Tget_size(type.get());
  return H5Tget_class(type.get());
}

std::vector<std::string> FlashFile::readStrings(const std::string& name) const {
  Handle set = open(name);
  const auto shape = dims(name, set);
  Handle fileType(H5Dget_type(set.get()), H5Tclose);
  if (!fileType.valid() || H5Tget_class(fileType.get()) != H5T_STRING)
    fail(name, "expected a string dataset");
  if (H5Tis_variable_str(fileType.get()) > 0)
    fail(name, "variable-length strings are not supported");
  const std::size_t width = H5Tget_size(fileType.get());
  const hsize_t count =
      std::accumulate(shape.begin(), shape.end(), hsize_t{1}, std::multiplies<>());
  Handle memType(H5Tcopy(H5T_C_S1), H5Tclose);
  if (!memType.valid() || H5Tset_size(memType.get(), width) < 0)
    fail(name, "cannot build the string type");
  std::vector<char> buffer(count * width + 1, '\0');
  if (count > 0 &&
      H5Dread(set.get(), memType.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, buffer.data()) < 0)
    fail(name, "cannot read the data");
  std::vector<std::string> result;
  for (hsize_t i = 0; i < count; ++i) {
    std::string s(buffer.data() + i * width, width);
    s.erase(std::find(s.begin(), s.end(), '\0'), s.end());
    const auto first = s.find_first_not_of(' ');
    const auto last = s.find_last_not_of(' ');
    result.push_back(first == std::string::npos ? "" : s.substr(first, last - first + 1));
  }
  return result;
}

template <typename T>
std::vector<std::pair<std::string, T>> FlashFile::readPairs(const std::string& name) const {
  if (!has(name)) return {};
  Handle set = open(name);
  const auto shape = dims(name, set);
  Handle fileType(H5Dget_type(set.get()), H5Tclose);
  if (!fileType.valid() || H5Tget_class(fileType.get()) != H5T_COMPOUND)
    fail(name, "expected a compound dataset of name/value pairs");
  const int nameIndex = H5Tget_member_index(fileType.get(), "name");
  const int valueIndex = H5Tget_member_index(fileType.get(), "value");
  if (nameIndex < 0 || valueIndex < 0) fail(name, "expected compound members 'name' and 'value'");
  const auto fixedStringWidth = [&](int member, const char* what) {
    Handle type(H5Tget_member_type(fileType.get(), static_cast<unsigned>(member)), H5Tclose);
    if (!type.valid() || H5Tget_class(type.get()) != H5T_STRING ||
        H5Tis_variable_str(type.get()) > 0)
      fail(name, fmt::format("member '{}' is not a fixed-length string", what));
    return H5Tget_size(type.get());
  };
  const std::size_t nameWidth = fixedStringWidth(nameIndex, "name");
  const hsize_t count =
      std::accumulate(shape.begin(), shape.end(), hsize_t{1}, std::multiplies<>());

  // Names and values are read separately, each through a one-member compound type.
  Handle nameMem(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(nameMem.get(), nameWidth);
  Handle namesOnly(H5Tcreate(H5T_COMPOUND, nameWidth), H5Tclose);
  if (!namesOnly.valid() || H5Tinsert(namesOnly.get(), "name", 0, nameMem.get()) < 0)
    fail(name, "cannot build the compound type");
  std::vector<char> names(count * nameWidth + 1, '\0');
  if (count > 0 &&
      H5Dread(set.get(), namesOnly.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, names.data()) < 0)
    fail(name, "cannot read the names");

  std::size_t valueWidth = sizeof(T);
  Handle valueMem;
  if constexpr (std::is_same_v<T, std::string>) {
    valueWidth = fixedStringWidth(valueIndex, "value");
    valueMem = Handle(H5Tcopy(H5T_C_S1), H5Tclose);
    H5Tset_size(valueMem.get(), valueWidth);
  } else {
    valueMem = Handle(H5Tcopy(std::is_same_v<T, int> ? H5T_NATIVE_INT : H5T_NATIVE_DOUBLE),
                      H5Tclose);
  }
  Handle valuesOnly(H5Tcreate(H5T_COMPOUND, valueWidth), H5Tclose);
  if (!valueMem.valid() || !valuesOnly.valid() ||
      H5Tinsert(valuesOnly.get(), "value", 0, valueMem.get()) < 0)
    fail(name, "cannot build the compound type");
  std::vector<char> values(count * valueWidth + 1, '\0');
  if (count > 0 &&
      H5Dread(set.get(), valuesOnly.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0)
    fail(name, "cannot read the values");

  std::vector<std::pair<std::string, T>> result;
  for (hsize_t i = 0; i < count; ++i) {
    T value;
    if constexpr (std::is_same_v<T, std::string>)
      value = trimmedText(values.data() + i * valueWidth, valueWidth);
    else
      std::memcpy(&value, values.data() + i * valueWidth, sizeof(T));
    result.emplace_back(trimmedText(names.data() + i * nameWidth, nameWidth), value);
  }
  return result;
}

template std::vector<std::pair<std::string, int>> FlashFile::readPairs(const std::string&) const;
template std::vector<std::pair<std::string, double>> FlashFile::readPairs(
    const std::string&) const;
template std::vector<std::pair<std::string, std::string>> FlashFile::readPairs(
    const std::string&) const;

}  // namespace amrstream::formats::flash
