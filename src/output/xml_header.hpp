#pragma once
// The element tree of a VTK XML file's header, parsed by expat (Debian's libexpat) up to the "_"
// that opens <AppendedData>: the bytes after it are not XML (raw data may hold anything, '<'
// included), so parsing stops at that start tag and the caller reads the rest by offset.
//
// Expat checks well-formedness and the encoding, and decodes entities and character references.
// On top of it: a document that declares entities is refused, so nothing is expanded beyond the
// predefined entities; elements nested deeper than 64 are refused; the tree and its text take
// memory in proportion to the header's size.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace amrstream::output {

struct XmlElement {
  std::string name;
  std::vector<std::pair<std::string, std::string>> attributes;  // decoded, in file order
  std::vector<XmlElement> children;
  std::string text;  // character data directly inside the element (not its children), decoded

  // nullptr when absent.
  const std::string* attribute(std::string_view key) const;
  std::vector<const XmlElement*> childrenNamed(std::string_view childName) const;
  // The first child of that name, or nullptr.
  const XmlElement* child(std::string_view childName) const;
  // The first DataArray child whose Name attribute is `arrayName`, or nullptr.
  const XmlElement* dataArray(std::string_view arrayName) const;
};

struct XmlHeader {
  XmlElement root;
  // Index of the byte after the "_" that opens <AppendedData>; empty when the file has none.
  std::optional<std::size_t> appendedStart;
};

// Parses `bytes` up to the appended data (or to the end). Throws amrstream::InputError naming
// `source` and, for text that is not well-formed, the line and column and expat's reason; a file
// that ends with elements open is reported as truncated.
XmlHeader parseXmlHeader(std::string_view bytes, const std::string& source);

// Helpers shared with the DataArray reader.
bool isXmlSpace(char c);
std::string_view trimmedXmlSpace(std::string_view text);
// At most 40 characters of `text` for a message, non-printable bytes shown as '?'.
std::string excerpt(std::string_view text);

}  // namespace amrstream::output
