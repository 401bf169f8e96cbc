#include "output/vtk_xml_appended.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace amrstream::output {

std::string xmlAttribute(std::string_view text) {
  std::string escaped;
  escaped.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&':
        escaped += "&amp;";
        break;
      case '<':
        escaped += "&lt;";
        break;
      case '>':
        escaped += "&gt;";
        break;
      case '"':
        escaped += "&quot;";
        break;
      case '\'':
        escaped += "&apos;";
        break;
      // Unescaped, XML turns these into spaces inside attribute values.
      case '\t':
        escaped += "&#9;";
        break;
      case '\n':
        escaped += "&#10;";
        break;
      case '\r':
        escaped += "&#13;";
        break;
      default:
        escaped += c;
    }
  }
  return escaped;
}

std::vector<std::uint64_t> appendedOffsets(const std::vector<const AppendedArray*>& arrays) {
  std::vector<std::uint64_t> offsets;
  std::uint64_t offset = 0;
  for (const AppendedArray* array : arrays) {
    offsets.push_back(offset);
    offset += sizeof(std::uint64_t) + array->byteCount;
  }
  return offsets;
}

std::string dataArrayTag(const AppendedArray& array, std::uint64_t offset, int indent) {
  return fmt::format(
      "{:{}}<DataArray type=\"{}\" Name=\"{}\" NumberOfComponents=\"{}\" format=\"appended\" "
      "offset=\"{}\"/>\n",
      "", indent, array.type, xmlAttribute(array.name), array.components, offset);
}

void writeAppendedData(BufferedWriter& out, const std::vector<const AppendedArray*>& arrays) {
  out.write("  <AppendedData encoding=\"raw\">\n   _");
  for (const AppendedArray* array : arrays) {
    out.put<std::uint64_t>(array->byteCount);
    const std::uint64_t start = out.bytesWritten();
    array->writeValues(out);
    const std::uint64_t written = out.bytesWritten() - start;
    if (written != array->byteCount) {
      throw std::logic_error(fmt::format("VTK array '{}' declared {} bytes but wrote {}",
                                         array->name, array->byteCount, written));
    }
  }
  out.write("\n  </AppendedData>\n");
}

}  // namespace amrstream::output
