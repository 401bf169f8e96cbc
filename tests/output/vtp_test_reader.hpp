#pragma once
// A reader for the .vtp files amrstream writes, for tests only: independent of the writer's
// code, it parses the XML tags before the appended section (a tolerant scan of tag names and
// attributes, not a general XML parser) and slices the raw appended blocks with the UInt64
// byte counts, checking that every block lies inside the section and the section is closed.

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
  std::string section;  // enclosing element: "PointData", "CellData", "Points" or "Lines"
  XmlAttributes attributes;
  std::vector<std::byte> bytes;  // the block's payload

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
