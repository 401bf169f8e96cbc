#pragma once
// Structure-aware HDF5 inputs: a "recipe" of bytes that decodes, whatever the bytes, into the
// groups and datasets of a valid HDF5 file (names, types, shapes, storage and data), which the
// harness writes and the reader under test then opens. libhdf5 itself only ever parses files it
// wrote, so the fuzzer explores our readers' handling of shapes, types, strings, declared sizes
// and values rather than libhdf5's parser of corrupt files.
//
// Recipe := Op*, each Op chosen by a byte modulo 3:
//   0 dataset: NAME TYPE RANK DIM* LAYOUT DATA
//   1 group:   NAME (later datasets go into it)
//   2 end:     close the innermost open group
// NAME: a byte < 0xE0 picks kRecipeNames[byte % size]; otherwise a length byte and that many
//   raw bytes follow.
// TYPE: a byte modulo RecipeType's count, then for strings a width byte (1 + b % 80) and a
//   padding byte (null-terminated, null-padded, space-padded).
// RANK: a byte modulo 5; DIM: LEB128, at most 2^40.
// LAYOUT: a byte modulo 4 (RecipeLayout). A dataset of more than kMaxRecipeValues values, or
//   with a zero dimension and a chunked layout, is declared without data (chunked, unwritten).
// DATA: the values in the file type's byte layout (compound members one after the other;
//   a variable-length string is a length byte and its bytes), zeros once the recipe ends.
// Decoding stops after kMaxRecipeOps ops or at the recipe's end.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace amrstream::fuzz {

inline constexpr std::size_t kMaxRecipeOps = 96;
inline constexpr std::uint64_t kMaxRecipeValues = 1 << 16;

enum class RecipeType : std::uint8_t {
  kInt32Le,
  kInt32Be,
  kInt64Le,
  kFloat32Le,
  kFloat32Be,
  kFloat64Le,
  kFloat64Be,
  kUint8,
  kFixedString,
  kVariableString,
  kPairFixedInt,     // {name: fixed string, value: int32}
  kPairFixedDouble,  // {name: fixed string, value: float64}
  kPairFixedFixed,   // {name: fixed string, value: fixed string of the same width}
  kPairVariableVariable,
  kPairVariableInt,
  kCount
};

enum class RecipeLayout : std::uint8_t { kContiguous, kChunked, kChunkedDeflate, kUnwritten };

enum class StringPad : std::uint8_t { kNullTerminated, kNullPadded, kSpacePadded };

// Names the readers look for, so that a mutated byte still names something they read.
extern const std::vector<std::string> kRecipeNames;

// Writes the HDF5 file `recipe` decodes to at `path`; false when HDF5 cannot create the file.
bool writeRecipeFile(std::span<const std::uint8_t> recipe, const std::filesystem::path& path);

// Builds recipes, for seed inputs.
class RecipeWriter {
 public:
  void group(const std::string& name);
  void end();
  // `data`: the values in the type's byte layout, as DATA above.
  void dataset(const std::string& name, RecipeType type, const std::vector<std::uint64_t>& dims,
               std::string_view data, RecipeLayout layout = RecipeLayout::kContiguous,
               int stringWidth = 0, StringPad pad = StringPad::kNullTerminated);
  const std::string& bytes() const { return bytes_; }

 private:
  void name(const std::string& name);
  void varint(std::uint64_t value);
  std::string bytes_;
};

// Little-endian bytes of values, for RecipeWriter data.
template <typename T>
std::string littleEndianBytes(const std::vector<T>& values) {
  return std::string(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
}

}  // namespace amrstream::fuzz
