#include "hdf5_recipe.hpp"

#include <hdf5.h>

#include <algorithm>
#include <deque>

#include "formats/hdf5_handle.hpp"

namespace amrstream::fuzz {

using formats::Hdf5Handle;

const std::vector<std::string> kRecipeNames = {
    // FLASH
    "unknown names", "refine level", "node type", "bounding box", "block size", "coordinates",
    "gid", "integer scalars", "integer runtime parameters", "real scalars",
    "real runtime parameters", "string scalars", "string runtime parameters", "logical scalars",
    "dens", "velx", "vely", "velz", "pres", "temp",
    // Enzo
    "Grid00000001", "Grid00000002", "Grid00000003", "Grid00000004", "Density", "x-velocity",
    "y-velocity", "z-velocity", "particle_mass", "Level", "LeftEdges", "RightEdges",
    "ActiveDimensions", "ParentIDs",
    // others
    "level_0", "data", "name", "value"};

namespace {

constexpr std::uint64_t kMaxDimension = std::uint64_t{1} << 40;
constexpr std::uint64_t kMaxFileDataBytes = std::uint64_t{1} << 20;
constexpr std::size_t kMaxGroupDepth = 8;
constexpr std::uint8_t kRawNameMark = 0xE0;

class RecipeBytes {
 public:
  explicit RecipeBytes(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}
  bool done() const { return position_ >= bytes_.size(); }
  std::uint8_t next() { return done() ? 0 : bytes_[position_++]; }
  std::uint64_t varint() {
    std::uint64_t value = 0;
    for (int shift = 0; shift < 64; shift += 7) {
      const std::uint8_t byte = next();
      value |= std::uint64_t(byte & 0x7f) << shift;
      if ((byte & 0x80) == 0) break;
    }
    return std::min(value, kMaxDimension);
  }
  // `n` bytes, zeros past the end.
  void take(char* into, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) into[i] = static_cast<char>(next());
  }

 private:
  std::span<const std::uint8_t> bytes_;
  std::size_t position_ = 0;
};

std::string readName(RecipeBytes& in) {
  const std::uint8_t pick = in.next();
  if (pick < kRawNameMark) return kRecipeNames[pick % kRecipeNames.size()];
  std::string name(in.next() % 48, '\0');
  in.take(name.data(), name.size());
  return name;
}

// How one member of an element is filled from the recipe.
struct Member {
  std::size_t offset;
  std::size_t bytes;  // 0: a variable-length string (a char* in memory)
};

struct ElementType {
  Hdf5Handle type;
  std::size_t size = 0;
  std::vector<Member> members;
};

Hdf5Handle stringType(std::size_t width, StringPad pad) {
  Hdf5Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  if (width == 0) {
    H5Tset_size(type.get(), H5T_VARIABLE);
  } else {
    H5Tset_size(type.get(), width);
    H5Tset_strpad(type.get(), pad == StringPad::kNullPadded    ? H5T_STR_NULLPAD
                              : pad == StringPad::kSpacePadded ? H5T_STR_SPACEPAD
                                                               : H5T_STR_NULLTERM);
  }
  return type;
}

ElementType pair(Hdf5Handle name, std::size_t nameBytes, Hdf5Handle value, std::size_t valueBytes) {
  const std::size_t nameSize = nameBytes == 0 ? sizeof(char*) : nameBytes;
  const std::size_t valueSize = valueBytes == 0 ? sizeof(char*) : valueBytes;
  ElementType element{Hdf5Handle(H5Tcreate(H5T_COMPOUND, nameSize + valueSize), H5Tclose),
                      nameSize + valueSize,
                      {{0, nameBytes}, {nameSize, valueBytes}}};
  H5Tinsert(element.type.get(), "name", 0, name.get());
  H5Tinsert(element.type.get(), "value", nameSize, value.get());
  return element;
}

ElementType readType(RecipeBytes& in) {
  const auto code = static_cast<RecipeType>(in.next() % std::uint8_t(RecipeType::kCount));
  const auto fixed = [](hid_t predefined) {
    const std::size_t size = H5Tget_size(predefined);
    return ElementType{Hdf5Handle(H5Tcopy(predefined), H5Tclose), size, {{0, size}}};
  };
  const auto width = [&] { return std::size_t(1 + in.next() % 80); };
  const auto pad = [&] { return static_cast<StringPad>(in.next() % 3); };
  switch (code) {
    case RecipeType::kInt32Le:
      return fixed(H5T_STD_I32LE);
    case RecipeType::kInt32Be:
      return fixed(H5T_STD_I32BE);
    case RecipeType::kInt64Le:
      return fixed(H5T_STD_I64LE);
    case RecipeType::kFloat32Le:
      return fixed(H5T_IEEE_F32LE);
    case RecipeType::kFloat32Be:
      return fixed(H5T_IEEE_F32BE);
    case RecipeType::kFloat64Le:
      return fixed(H5T_IEEE_F64LE);
    case RecipeType::kFloat64Be:
      return fixed(H5T_IEEE_F64BE);
    case RecipeType::kUint8:
      return fixed(H5T_STD_U8LE);
    case RecipeType::kFixedString: {
      const std::size_t w = width();
      return ElementType{stringType(w, pad()), w, {{0, w}}};
    }
    case RecipeType::kVariableString:
      return ElementType{stringType(0, StringPad::kNullTerminated), sizeof(char*), {{0, 0}}};
    case RecipeType::kPairFixedInt: {
      const std::size_t w = width();
      return pair(stringType(w, pad()), w, Hdf5Handle(H5Tcopy(H5T_STD_I32LE), H5Tclose), 4);
    }
    case RecipeType::kPairFixedDouble: {
      const std::size_t w = width();
      return pair(stringType(w, pad()), w, Hdf5Handle(H5Tcopy(H5T_IEEE_F64LE), H5Tclose), 8);
    }
    case RecipeType::kPairFixedFixed: {
      const std::size_t w = width();
      const StringPad p = pad();
      return pair(stringType(w, p), w, stringType(w, p), w);
    }
    case RecipeType::kPairVariableVariable:
      return pair(stringType(0, StringPad::kNullTerminated), 0,
                  stringType(0, StringPad::kNullTerminated), 0);
    case RecipeType::kPairVariableInt:
    case RecipeType::kCount:
      break;
  }
  return pair(stringType(0, StringPad::kNullTerminated), 0,
              Hdf5Handle(H5Tcopy(H5T_STD_I32LE), H5Tclose), 4);
}

class RecipeFile {
 public:
  explicit RecipeFile(hid_t file) : file_(file) {}

  void run(RecipeBytes& in) {
    for (std::size_t op = 0; op < kMaxRecipeOps && !in.done(); ++op) {
      switch (in.next() % 3) {
        case 0:
          dataset(in);
          break;
        case 1: {
          const std::string name = readName(in);
          if (groups_.size() >= kMaxGroupDepth) break;
          Hdf5Handle group(H5Gcreate2(where(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                           H5Gclose);
          if (group.valid()) groups_.push_back(std::move(group));
          break;
        }
        default:
          if (!groups_.empty()) groups_.pop_back();
      }
    }
  }

 private:
  hid_t where() const { return groups_.empty() ? file_ : groups_.back().get(); }

  void dataset(RecipeBytes& in) {
    const std::string name = readName(in);
    const ElementType element = readType(in);
    const int rank = in.next() % 5;
    std::vector<hsize_t> dims(rank);
    std::uint64_t count = 1;
    bool overflow = false;
    for (hsize_t& d : dims) {
      d = in.varint();
      overflow |= d != 0 && count > ~std::uint64_t{0} / d;
      count *= overflow ? 1 : d;
    }
    auto layout = static_cast<RecipeLayout>(in.next() % 4);
    const bool empty = std::ranges::find(dims, hsize_t{0}) != dims.end();
    const std::uint64_t dataBytes = empty ? 0 : count * element.size;
    if (overflow || count > kMaxRecipeValues || written_ + dataBytes > kMaxFileDataBytes)
      layout = RecipeLayout::kUnwritten;
    const bool chunkable = rank > 0 && !empty;

    const Hdf5Handle space(
        rank == 0 ? H5Screate(H5S_SCALAR) : H5Screate_simple(rank, dims.data(), nullptr), H5Sclose);
    const Hdf5Handle create(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
    if (!space.valid() || !create.valid() || !element.type.valid()) return;
    if (layout != RecipeLayout::kContiguous && chunkable) {
      std::vector<hsize_t> chunk(dims);
      for (hsize_t& c : chunk) c = std::min<hsize_t>(c, 8);
      H5Pset_chunk(create.get(), rank, chunk.data());
      if (layout == RecipeLayout::kChunkedDeflate) H5Pset_deflate(create.get(), 6);
    }
    const Hdf5Handle set(H5Dcreate2(where(), name.c_str(), element.type.get(), space.get(),
                                    H5P_DEFAULT, create.get(), H5P_DEFAULT),
                         H5Dclose);
    if (!set.valid() || layout == RecipeLayout::kUnwritten || empty) return;

    std::vector<char> buffer(dataBytes);
    std::deque<std::string> strings;  // a deque keeps the c_str() pointers valid
    for (std::uint64_t i = 0; i < count; ++i)
      for (const Member& member : element.members) {
        char* at = buffer.data() + i * element.size + member.offset;
        if (member.bytes > 0) {
          in.take(at, member.bytes);
          continue;
        }
        std::string& text = strings.emplace_back(in.next() % 64, '\0');
        in.take(text.data(), text.size());
        const char* pointer = text.c_str();
        std::copy_n(reinterpret_cast<const char*>(&pointer), sizeof pointer, at);
      }
    H5Dwrite(set.get(), element.type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, buffer.data());
    written_ += dataBytes;
  }

  hid_t file_;
  std::vector<Hdf5Handle> groups_;
  std::uint64_t written_ = 0;
};

}  // namespace

bool writeRecipeFile(std::span<const std::uint8_t> recipe, const std::filesystem::path& path) {
  const Hdf5Handle access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  // In memory until closed, then written out once.
  if (!access.valid() || H5Pset_fapl_core(access.get(), 1 << 16, 1) < 0) return false;
  const Hdf5Handle file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access.get()),
                        H5Fclose);
  if (!file.valid()) return false;
  RecipeBytes in(recipe);
  RecipeFile(file.get()).run(in);
  return true;
}

void RecipeWriter::group(const std::string& groupName) {
  bytes_ += char(1);
  name(groupName);
}

void RecipeWriter::end() { bytes_ += char(2); }

void RecipeWriter::dataset(const std::string& datasetName, RecipeType type,
                           const std::vector<std::uint64_t>& dims, std::string_view data,
                           RecipeLayout layout, int stringWidth, StringPad pad) {
  bytes_ += char(0);
  name(datasetName);
  bytes_ += char(type);
  const bool fixedName = type == RecipeType::kFixedString || type == RecipeType::kPairFixedInt ||
                         type == RecipeType::kPairFixedDouble ||
                         type == RecipeType::kPairFixedFixed;
  if (fixedName) {
    bytes_ += char(stringWidth - 1);
    bytes_ += char(pad);
  }
  bytes_ += char(dims.size());
  for (std::uint64_t d : dims) varint(d);
  bytes_ += char(layout);
  bytes_ += data;
}

void RecipeWriter::name(const std::string& text) {
  const auto known = std::ranges::find(kRecipeNames, text);
  if (known != kRecipeNames.end()) {
    bytes_ += char(known - kRecipeNames.begin());
    return;
  }
  bytes_ += char(0xFF);
  bytes_ += char(text.size());
  bytes_ += text;
}

void RecipeWriter::varint(std::uint64_t value) {
  do {
    const std::uint8_t low = value & 0x7f;
    value >>= 7;
    bytes_ += char(value != 0 ? low | 0x80 : low);
  } while (value != 0);
}

}  // namespace amrstream::fuzz
