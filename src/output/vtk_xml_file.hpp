#pragma once
// Reading side of VTK's XML file formats, independent of the dataset type: the <VTKFile>
// header (xml_header.hpp gives its element tree) and the values of its DataArrays. The
// counterpart of vtk_xml_appended.hpp.
//
// DataArray formats read: format="appended" with <AppendedData encoding="raw"> or "base64",
// format="binary" (inline base64) and format="ascii"; header_type UInt32 or UInt64; byte_order
// LittleEndian or BigEndian; types Int8 .. UInt64, Float32 and Float64; uncompressed, or
// compressed by vtkZLibDataCompressor or vtkLZ4DataCompressor (compressor="..." on <VTKFile>;
// the block layout is in vtk_compression.hpp). Other compressors (vtkLZMADataCompressor) are
// refused with a message naming the ones read.
//
// In base64, VTK encodes an uncompressed array's byte count together with its bytes, but a
// compressed array's block header on its own (padded with '=') and then all its compressed
// blocks as one more base64 run; both are read that way.
//
// Every problem throws amrstream::InputError naming the file (and the array, for its data). The
// path must name a regular file (a FIFO or a device is refused before it is opened) that fits in
// 3/4 of the memory and keeps its size while it is read. Nothing is read past the file's end, no
// allocation is sized by an attribute before the data to fill it has been found, and no array's
// converted values may exceed 3/4 of the memory. For compressed arrays: the block count and the
// compressed sizes must fit in the bytes left in the file, a block may not claim more bytes than
// its compressor can inflate its compressed bytes to, the total must equal NumberOfTuples x
// components (where the caller knows it) before anything is decompressed, and every block must
// inflate to exactly the size its header declares. Blocks are decompressed a batch at a time
// (vtk_compression.hpp) straight into the converted values.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "output/vtk_compression.hpp"
#include "output/xml_header.hpp"

namespace amrstream::output {

// A whole VTK XML file held in memory (the raw appended blocks are read in place, so it is
// neither copied nor moved).
class VtkXmlFile {
 public:
  // Reads and scans the file and checks the <VTKFile> attributes this reader depends on.
  explicit VtkXmlFile(const std::filesystem::path& path);
  VtkXmlFile(const VtkXmlFile&) = delete;
  VtkXmlFile& operator=(const VtkXmlFile&) = delete;

  const XmlElement& root() const { return root_; }  // <VTKFile>
  std::string datasetType() const;                  // the type attribute: "PolyData", ...

  // Throws InputError naming the file, with `problem`.
  [[noreturn]] void fail(const std::string& problem) const;

  // An unsigned integer attribute of `element`; `fallback` when absent (throws when absent
  // without fallback, or when not a decimal number).
  std::uint64_t count(const XmlElement& element, std::string_view key,
                      std::optional<std::uint64_t> fallback = std::nullopt) const;
  // NumberOfComponents of a DataArray (1 when absent).
  int components(const XmlElement& dataArray) const;

  // The values of a DataArray converted to the result type, checked to hold `tuples` tuples of
  // `components` values (any whole number of tuples when `tuples` is empty). `what` names the
  // array in messages, e.g. "Points" or "Lines/offsets". Floats: Float64 values beyond the range
  // of float become infinities. Integers: values must be whole and fit in int64.
  std::vector<float> floats(const XmlElement& dataArray, std::optional<std::uint64_t> tuples,
                            int components, const std::string& what) const;
  std::vector<double> doubles(const XmlElement& dataArray, std::optional<std::uint64_t> tuples,
                              int components, const std::string& what) const;
  std::vector<std::int64_t> integers(const XmlElement& dataArray,
                                     std::optional<std::uint64_t> tuples, int components,
                                     const std::string& what) const;
  // The strings of a type="String" array (each stored as its bytes and a terminating 0).
  std::vector<std::string> strings(const XmlElement& array, const std::string& what) const;

 private:
  struct Appended {
    std::size_t base = 0;  // index of the byte after "_"; offsets count from here
    bool base64 = false;   // encoding="base64" instead of "raw"
  };

  template <class T>
  std::vector<T> values(const XmlElement& dataArray, std::optional<std::uint64_t> tuples,
                        int expectedComponents, const std::string& what) const;
  void checkCount(std::uint64_t values, std::optional<std::uint64_t> tuples, int components,
                  const std::string& what) const;
  // An array's values, `bytesEach` once converted, must fit in the memory traces may take: a
  // compressed array may inflate a thousandfold.
  void checkFitsInMemory(std::uint64_t values, std::size_t bytesEach,
                         const std::string& what) const;
  // The payload of a format="binary" or format="appended" array; `decoded` holds it when it had
  // to be decoded from base64.
  std::span<const std::byte> inlineBlock(const XmlElement& dataArray, const std::string& what,
                                         std::vector<std::byte>& decoded) const;
  std::span<const std::byte> appendedBlock(const XmlElement& dataArray, const std::string& what,
                                           std::vector<std::byte>& decoded) const;
  // An integer of a block header (a byte count, a block count or size) at `header`.
  std::uint64_t headerValue(const std::byte* header) const;

  // A compressed array's block header and the bytes after it (its blocks and whatever follows).
  struct CompressedArray {
    BlockHeader header;
    std::span<const std::byte> blocks;
  };
  // Of a compressed format="binary" or format="appended" array; `decoded` holds the blocks when
  // they had to be decoded from base64.
  CompressedArray compressedArray(const XmlElement& dataArray, const std::string& what,
                                  std::vector<std::byte>& decoded) const;
  CompressedArray compressedFromRaw(std::span<const std::byte> bytes,
                                    const std::string& what) const;
  CompressedArray compressedFromBase64(std::string_view text, const std::string& what,
                                       std::vector<std::byte>& decoded) const;

  std::string source_;
  std::string bytes_;
  XmlElement root_;
  std::optional<Appended> appended_;
  bool swapBytes_ = false;       // the file's byte_order differs from this machine's
  std::size_t headerBytes_ = 4;  // size of a block's byte count: header_type UInt32 or UInt64
  Compression compression_ = Compression::None;
};

}  // namespace amrstream::output
