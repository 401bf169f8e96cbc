#include "formats/flash/flash_file.hpp"

#include "amrstream/error.hpp"
#include "util/input_file.hpp"

namespace amrstream::formats::flash {

namespace {

std::string withoutTrailingBlanks(std::string s) {
  s.erase(s.find_last_not_of(' ') + 1);
  return s;
}

std::string withoutBlanks(const std::string& s) {
  const auto first = s.find_first_not_of(' ');
  const auto last = s.find_last_not_of(' ');
  return first == std::string::npos ? "" : s.substr(first, last - first + 1);
}

}  // namespace

FlashFile::FlashFile(const std::filesystem::path& path) : path_(path.string()) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  regularFileSize(path);  // refuses a directory or FIFO before HDF5 opens it
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

std::vector<double> FlashFile::readBlocks(const std::string& name,
                                          const std::vector<std::size_t>& blocks) const {
  const Handle set = open(name);
  std::vector<hsize_t> shape = dims(name, set);
  std::size_t size = 0;
  if (typeClass(name, set, &size) != H5T_FLOAT || (size != 4 && size != 8))
    fail(name, "expected float32 or float64 data");
  requireStoredValues(set.get(), path_, name);
  hsize_t perBlock = 1;
  for (std::size_t a = 1; a < shape.size(); ++a) perBlock *= shape[a];
  std::vector<double> values(blocks.size() * perBlock);
  if (blocks.empty() || perBlock == 0) return values;
  const Handle space(H5Dget_space(set.get()), H5Sclose);
  if (!space.valid() || H5Sselect_none(space.get()) < 0) fail(name, "cannot read the dataspace");
  std::vector<hsize_t> start(shape.size(), 0), count = shape;
  for (std::size_t i = 0; i < blocks.size();) {
    std::size_t run = 1;
    while (i + run < blocks.size() && blocks[i + run] == blocks[i] + run) ++run;
    if (blocks[i] + run > shape[0]) fail(name, fmt::format("has no block {}", blocks[i] + run - 1));
    start[0] = blocks[i];
    count[0] = run;
    if (H5Sselect_hyperslab(space.get(), H5S_SELECT_OR, start.data(), nullptr, count.data(),
                            nullptr) < 0)
      fail(name, "cannot select its blocks");
    i += run;
  }
  const hsize_t all = values.size();
  const Handle memory(H5Screate_simple(1, &all, nullptr), H5Sclose);
  if (!memory.valid() || H5Dread(set.get(), H5T_NATIVE_DOUBLE, memory.get(), space.get(),
                                 H5P_DEFAULT, values.data()) < 0)
    fail(name, "cannot read the data");
  return values;
}

std::vector<std::string> FlashFile::readStrings(const std::string& name) const {
  Handle set = open(name);
  Handle fileType(H5Dget_type(set.get()), H5Tclose);
  if (!fileType.valid() || H5Tget_class(fileType.get()) != H5T_STRING)
    fail(name, "expected a string dataset");
  const std::uint64_t count = requireStoredValues(set.get(), path_, name);
  const auto strings = readHdf5Strings(set.get(), fileType.get(), nullptr, count);
  if (!strings) fail(name, "cannot read the strings");
  std::vector<std::string> result;
  for (const std::string& s : *strings) result.push_back(withoutBlanks(s));
  return result;
}

template <typename T>
std::vector<std::pair<std::string, T>> FlashFile::readPairs(const std::string& name) const {
  if (!has(name)) return {};
  Handle set = open(name);
  Handle fileType(H5Dget_type(set.get()), H5Tclose);
  if (!fileType.valid() || H5Tget_class(fileType.get()) != H5T_COMPOUND)
    fail(name, "expected a compound dataset of name/value pairs");
  const int nameIndex = H5Tget_member_index(fileType.get(), "name");
  const int valueIndex = H5Tget_member_index(fileType.get(), "value");
  if (nameIndex < 0 || valueIndex < 0) fail(name, "expected compound members 'name' and 'value'");
  const std::uint64_t count = requireStoredValues(set.get(), path_, name);
  const auto strings = [&](int member, const char* what) {
    Handle type(H5Tget_member_type(fileType.get(), static_cast<unsigned>(member)), H5Tclose);
    if (!type.valid() || H5Tget_class(type.get()) != H5T_STRING)
      fail(name, fmt::format("member '{}' is not a string", what));
    auto read = readHdf5Strings(set.get(), type.get(), what, count);
    if (!read) fail(name, fmt::format("cannot read the {}s", what));
    for (std::string& s : *read) s = withoutTrailingBlanks(std::move(s));
    return std::move(*read);
  };
  const std::vector<std::string> names = strings(nameIndex, "name");

  std::vector<T> values;
  if constexpr (std::is_same_v<T, std::string>) {
    values = strings(valueIndex, "value");
  } else {
    // The values alone, through a one-member compound type.
    const Handle valuesOnly(H5Tcreate(H5T_COMPOUND, sizeof(T)), H5Tclose);
    const hid_t valueType = std::is_same_v<T, int> ? H5T_NATIVE_INT : H5T_NATIVE_DOUBLE;
    if (!valuesOnly.valid() || H5Tinsert(valuesOnly.get(), "value", 0, valueType) < 0)
      fail(name, "cannot build the compound type");
    values.resize(count);
    if (count > 0 &&
        H5Dread(set.get(), valuesOnly.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0)
      fail(name, "cannot read the values");
  }
  std::vector<std::pair<std::string, T>> result;
  for (std::uint64_t i = 0; i < count; ++i) result.emplace_back(names[i], values[i]);
  return result;
}

template std::vector<std::pair<std::string, int>> FlashFile::readPairs(const std::string&) const;
template std::vector<std::pair<std::string, double>> FlashFile::readPairs(const std::string&) const;
template std::vector<std::pair<std::string, std::string>> FlashFile::readPairs(
    const std::string&) const;

}  // namespace amrstream::formats::flash
