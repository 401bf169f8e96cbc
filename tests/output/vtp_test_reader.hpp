#pragma once
// A reader for the .vtp files amrstream writes, for tests only: independent of the writer's
// code, it parses the XML tags before the appended section (a tolerant scan of tag names and
// attributes, not a general XML parser) and slices the raw appended blocks with the UInt64
// byte counts, checking that every block lies inside the section and the section is closed.
// Compressed files (compressor="vtkZLibDataCompressor" or "vtkLZ4DataCompressor") are read by
// VTK's block layout with zlib's uncompress and LZ4_decompress_safe, each block checked to
// inflate to the size the header gives.

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace amrstream::testing {

using XmlAttributes = std::map<std::string, std::string>;

struct VtpArray {
  // Enclosing element: "FieldData", "PointData", "CellData", "Points" or "Lines".
  std::string section;
  XmlAttributes attributes;
  std::vector<std::byte> bytes;  // the block's payload, decompressed
  // Compressed files: the block header as written (block count, block size, last block size,
  // compressed sizes).
  std::vector<std::uint64_t> blockHeader;

  std::string name() const { return attributes.at("Name"); }
  std::string type() const { return attributes.at("type"); }
  int components() const;

  template <class T>
  std::vector<T> values() const {
    if (bytes.size() % sizeof(T) != 0) throw std::runtime_error("block size not a multiple");
    std::vector<T> out(bytes.size() / sizeof(T));
    if (!out.empty()) std::memcpy(out.data(), bytes.data(), bytes.size());
    return out;
  }
};

struct VtpFile {
  XmlAttributes vtkFile;    // attributes of <VTKFile>
  XmlAttributes piece;      // attributes of <Piece>
  XmlAttributes pointData;  // attributes of <PointData>
  std::vector<VtpArray> arrays;

  // Throws std::runtime_error when the section has no array of that name.
  const VtpArray& array(const std::string& section, const std::string& name) const;
};

// Throws std::runtime_error on anything it does not understand.
VtpFile readVtp(const std::filesystem::path& path);

}  // namespace amrstream::testing
