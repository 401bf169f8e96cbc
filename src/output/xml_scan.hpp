#pragma once
// The element tree of a VTK XML file's header. Not a general XML parser: a careful scan of
// elements, attributes (quoted, with the five named entities and numeric character references),
// comments, processing instructions, declarations and CDATA, that stops at the "_" opening
// <AppendedData>, since the raw bytes after it may contain anything, '<' included.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace amrstream::output {

struct XmlElement {
  std::string name;
  std::vector<std::pair<std::string, std::string>> attributes;  // unescaped, in file order
  std::vector<XmlElement> children;
  // Character data directly inside the element (not inside its children), as views into the
  // scanned bytes; whitespace-only runs are left out.
  std::vector<std::string_view> text;

  // nullptr when absent.
  const std::string* attribute(std::string_view key) const;
  std::vector<const XmlElement*> childrenNamed(std::string_view childName) const;
  // The first child of that name, or nullptr.
  const XmlElement* child(std::string_view childName) const;
  // The first DataArray child whose Name attribute is `arrayName`, or nullptr.
  const XmlElement* dataArray(std::string_view arrayName) const;
};

struct ScannedXml {
  XmlElement root;
  // Index of the byte after the "_" that opens <AppendedData>; empty when the file has none.
  std::optional<std::size_t> appendedStart;
};

// Scans `bytes` up to the appended data (or to the end). Throws amrstream::InputError naming
// `source` and the byte offset of the problem on text that is not well-formed, on a truncated
// file (elements left open) and on elements nested deeper than 64.
ScannedXml scanXml(std::string_view bytes, const std::string& source);

// Helpers shared with the DataArray reader.
bool isXmlSpace(char c);
std::string_view trimmedXmlSpace(std::string_view text);
// At most 40 characters of `text` for a message, non-printable bytes shown as '?'.
std::string excerpt(std::string_view text);

}  // namespace amrstream::output
