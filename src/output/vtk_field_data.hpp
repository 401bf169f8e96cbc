#pragma once
// Dataset-level arrays (VTK's <FieldData>, written before the first <Piece>): provenance and
// other values that belong to the whole file rather than to points or cells.
//
// As VTK 9.1 writes them: a string array is `<Array type="String" NumberOfTuples="N" ...>` whose
// bytes are every string's UTF-8 bytes each followed by one NUL ("a", "", "bc" -> "a\0\0bc\0");
// numbers are `<DataArray type="Float64"|"Int64" NumberOfTuples="N" ...>`. One component each.

#include <cstdint>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "output/buffered_writer.hpp"

namespace amrstream::output {

struct FieldDataArray {
  std::string name;
  std::variant<std::vector<std::string>, std::vector<double>, std::vector<std::int64_t>> values;
};

// One-value arrays, the usual provenance record: textField("Input", "cloud.exa").
FieldDataArray textField(std::string name, std::string value);
FieldDataArray numberField(std::string name, double value);
// A setting held as a float, written as the double of its shortest decimal (1e-12, not the
// float's 9.99999996e-13).
FieldDataArray numberField(std::string name, float value);
FieldDataArray integerField(std::string name, std::int64_t value);

// "String", "Float64" or "Int64".
std::string_view vtkTypeName(const FieldDataArray& array);
std::uint64_t tupleCount(const FieldDataArray& array);
// Size of the array's bytes in the file, before compression.
std::uint64_t byteCount(const FieldDataArray& array);
// Throws std::invalid_argument naming the array when it cannot be written: a string that holds a
// NUL (it would be read back as two), or an empty name.
void checkWritable(const FieldDataArray& array);
// Writes those bytes (little endian, as the host) of a checked array.
void writeValues(BufferedWriter& out, const FieldDataArray& array);

}  // namespace amrstream::output
