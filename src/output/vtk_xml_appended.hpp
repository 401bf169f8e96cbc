#pragma once
// The parts of VTK's XML file format that do not depend on the dataset type: DataArray tags
// with format="appended", dataset-level <FieldData>, and the <AppendedData> section they point
// into, raw or compressed.
//
// What is written (VTK "XML file formats"; header_type="UInt64", byte_order LittleEndian): the
// section opens with "_", then each array's block, and a DataArray's offset is its block's
// position counted from the byte after "_". Uncompressed, a block is a UInt64 byte count
// followed by the bytes; compressed, VTK's block header and the compressed blocks
// (vtk_compression.hpp), and <VTKFile> carries compressor="...".
//
// Compressed sizes are known only once the blocks are written, so, as VTK does, the markup is
// written first with every offset a placeholder padded with spaces to a fixed width, each block
// header is written as zeros, and both are written over in place once their block is done.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "output/buffered_writer.hpp"
#include "output/vtk_compression.hpp"
#include "output/vtk_field_data.hpp"

namespace amrstream::output {

struct AppendedArray {
  std::string name;
  std::string_view type;  // VTK type name: "Float32", "Int32", "Int64"
  int components = 1;
  std::uint64_t byteCount = 0;  // size of the values before any compression
  // Streams exactly byteCount bytes of raw little-endian values into the writer, in any number of
  // writes; where they go (file or compressor) is not the producer's concern.
  std::function<void(BufferedWriter&)> writeValues = {};
  // Or: puts the values' bytes [first, first + out.size()) into `out`. Called from several
  // threads at once for disjoint ranges, so the writer can make and compress a batch of blocks in
  // parallel; when set, writeValues is not used.
  std::function<void(std::uint64_t first, std::span<std::byte> out)> fillValues = {};
};

// Escapes text for use inside a double-quoted XML attribute.
std::string xmlAttribute(std::string_view text);

// A VTK XML file whose arrays all live in <AppendedData>. The markup inside <VTKFile> is given in
// file order (markup, dataArray and fieldData calls); write() then writes it all.
class AppendedFileWriter {
 public:
  // Starts with <?xml ...?> and <VTKFile type="datasetType" ... compressor="...">.
  AppendedFileWriter(std::string_view datasetType, Compression compression);

  // Markup written as it is (escape attribute values with xmlAttribute).
  void markup(std::string_view xml);
  // `<DataArray .../>` for `array`, indented by `indent` spaces. `array` must outlive write().
  void dataArray(const AppendedArray& array, int indent);
  // `<FieldData>` with one tag per array (nothing when `arrays` is empty); the arrays are copied.
  // Throws std::invalid_argument for an array checkWritable refuses.
  void fieldData(const std::vector<FieldDataArray>& arrays, int indent);

  // Writes the markup, the appended blocks and the closing tags to `path` atomically (a failed
  // write leaves no file). Throws std::logic_error when an array writes another number of bytes
  // than it declared, std::runtime_error naming the path when the file cannot be written.
  void write(const std::filesystem::path& path) const;

 private:
  struct Slot {
    const AppendedArray* array;
    std::size_t offsetAt;  // index in markup_ of the placeholder after `offset=`
  };
  struct OwnedFieldArray {
    FieldDataArray values;
    AppendedArray appended;
  };

  void arrayTag(std::string_view element, const AppendedArray& array, std::string_view sizeKey,
                std::uint64_t size, int indent);

  Compression compression_;
  std::string markup_;
  std::vector<Slot> slots_;
  std::vector<std::unique_ptr<OwnedFieldArray>> fieldArrays_;  // stable addresses for slots_
};

}  // namespace amrstream::output
