#pragma once
// The parts of VTK's XML file format that do not depend on the dataset type: DataArray tags
// with format="appended" and the raw <AppendedData> section they point into.
//
// Conventions followed (VTK "XML file formats", header_type="UInt64", byte_order LittleEndian):
// the section opens with "_"; each array's block is a UInt64 byte count followed by that many
// bytes, and a DataArray's offset is the block's position counted from the byte after "_".

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "output/buffered_writer.hpp"

namespace amrstream::output {

struct AppendedArray {
  std::string name;
  std::string_view type;  // VTK type name: "Float32", "Int32", "Int64"
  int components = 1;
  std::uint64_t byteCount = 0;  // size of the block's payload
  // Streams exactly byteCount bytes of values into the writer.
  std::function<void(BufferedWriter&)> writeValues;
};

// Escapes text for use inside a double-quoted XML attribute.
std::string xmlAttribute(std::string_view text);

// Offsets of each array's block when the blocks are written in the order given.
std::vector<std::uint64_t> appendedOffsets(const std::vector<const AppendedArray*>& arrays);

// `<DataArray .../>` for an array whose block starts at `offset`; indented by `indent` spaces.
std::string dataArrayTag(const AppendedArray& array, std::uint64_t offset, int indent);

// Writes "<AppendedData>", the blocks in the order given, and "</AppendedData>". Throws
// std::logic_error if an array writes a different number of bytes than it declared.
void writeAppendedData(BufferedWriter& out, const std::vector<const AppendedArray*>& arrays);

}  // namespace amrstream::output
