#include "pvtp_writer.hpp"

#include <fmt/format.h>

#include <fstream>
#include <optional>
#include <string>

#include "amrstream/error.hpp"
#include "atomic_file.hpp"
#include "buffered_writer.hpp"
#include "vtk_xml_appended.hpp"
#include "xml_header.hpp"

namespace amrstream::output {

namespace {

// A .vtp's header: everything before its appended data (at most 64 MiB is read).
XmlHeader pieceHeader(const std::filesystem::path& piece) {
  std::ifstream in(piece, std::ios::binary);
  if (!in) throw InputError(piece.string(), "cannot open the piece");
  std::string bytes;
  constexpr std::size_t kChunk = std::size_t(1) << 16, kLimit = std::size_t(64) << 20;
  while (bytes.size() < kLimit) {
    const std::size_t had = bytes.size();
    bytes.resize(had + kChunk);
    in.read(bytes.data() + had, std::streamsize(kChunk));
    bytes.resize(had + std::size_t(in.gcount()));
    if (bytes.find("<AppendedData", had > 16 ? had - 16 : 0) != std::string::npos || !in) break;
  }
  return parseXmlHeader(bytes, piece.string());
}

std::string attributeOr(const XmlElement& e, std::string_view key, const std::string& fallback) {
  const std::string* value = e.attribute(key);
  return value ? *value : fallback;
}

// <PDataArray .../> for each DataArray of `group` (PointData, CellData or Points).
void declareArrays(BufferedWriter& out, const XmlElement* group, const char* parallelName,
                   const std::string& source) {
  out.write(fmt::format("    <{}>\n", parallelName));
  if (group)
    for (const XmlElement* array : group->childrenNamed("DataArray")) {
      const std::string* type = array->attribute("type");
      if (!type) throw InputError(source, "a DataArray has no type");
      out.write(fmt::format("      <PDataArray type=\"{}\"", xmlAttribute(*type)));
      if (const std::string* name = array->attribute("Name"))
        out.write(fmt::format(" Name=\"{}\"", xmlAttribute(*name)));
      out.write(fmt::format(" NumberOfComponents=\"{}\"/>\n",
                            xmlAttribute(attributeOr(*array, "NumberOfComponents", "1"))));
    }
  out.write(fmt::format("    </{}>\n", parallelName));
}

}  // namespace

void writePvtp(const std::filesystem::path& path,
               const std::vector<std::filesystem::path>& pieces) {
  if (pieces.empty()) throw InputError(path.string(), "no pieces to list");
  const std::string source = pieces.front().string();
  const XmlHeader header = pieceHeader(pieces.front());
  const XmlElement& file = header.root;
  const XmlElement* polyData = file.child("PolyData");
  const XmlElement* piece = polyData ? polyData->child("Piece") : nullptr;
  if (file.name != "VTKFile" || !piece) throw InputError(source, "not a VTK PolyData file");

  std::optional<AtomicFile> target;
  try {
    target.emplace(path);
    BufferedWriter out(*target);
    out.write("<?xml version=\"1.0\"?>\n");
    out.write(fmt::format(
        "<VTKFile type=\"PPolyData\" version=\"{}\" byte_order=\"{}\" header_type=\"{}\">\n",
        xmlAttribute(attributeOr(file, "version", "1.0")),
        xmlAttribute(attributeOr(file, "byte_order", "LittleEndian")),
        xmlAttribute(attributeOr(file, "header_type", "UInt64"))));
    out.write("  <PPolyData GhostLevel=\"0\">\n");
    declareArrays(out, piece->child("PointData"), "PPointData", source);
    declareArrays(out, piece->child("CellData"), "PCellData", source);
    declareArrays(out, piece->child("Points"), "PPoints", source);
    for (const std::filesystem::path& p : pieces)
      out.write(fmt::format("    <Piece Source=\"{}\"/>\n", xmlAttribute(p.filename().string())));
    out.write("  </PPolyData>\n</VTKFile>\n");
    out.flush();
    target->commit();
  } catch (const std::system_error& e) {
    throw InputError(path.string(), fmt::format("cannot write the .pvtp ({})", e.code().message()));
  }
}

}  // namespace amrstream::output
