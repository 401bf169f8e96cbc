#include "output/xml_header.hpp"

#include <expat.h>
#include <fmt/format.h>

#include <algorithm>
#include <memory>
#include <new>
#include <type_traits>

#include "amrstream/error.hpp"

namespace amrstream::output {
namespace {

// Deeper nesting than any VTK file has; the limit keeps a hostile file from exhausting the stack
// when the element tree is destroyed.
constexpr std::size_t kMaxDepth = 64;
// Expat takes its input's length as an int, so the file goes in pieces.
constexpr std::size_t kPieceBytes = std::size_t(1) << 20;

// Builds the element tree from expat's events.
class HeaderParser {
 public:
  HeaderParser(std::string_view bytes, const std::string& source)
      : bytes_(bytes), source_(source), parser_(XML_ParserCreate(nullptr), &XML_ParserFree) {
    if (!parser_) throw std::bad_alloc();
    XML_SetUserData(parser_.get(), this);
    XML_SetElementHandler(parser_.get(), onStart, onEnd);
    XML_SetCharacterDataHandler(parser_.get(), onText);
    XML_SetEntityDeclHandler(parser_.get(), onEntityDeclaration);
  }

  XmlHeader parse() {
    // Expat would say "syntax error" for both.
    const std::string_view content =
        trimmedXmlSpace(bytes_.substr(bytes_.starts_with("\xEF\xBB\xBF") ? 3 : 0));
    if (content.empty()) throw InputError(source_, "the file is empty");
    if (!content.starts_with('<')) {
      throw InputError(source_, "not an XML file (expected a VTK XML PolyData file, .vtp)");
    }
    bool finished = false;
    for (std::size_t at = 0; !finished;) {
      const std::size_t size = std::min(kPieceBytes, bytes_.size() - at);
      finished = at + size == bytes_.size();
      if (XML_Parse(parser_.get(), bytes_.data() + at, static_cast<int>(size), finished) !=
          XML_STATUS_OK) {
        if (appendedStart_) break;  // stopped at <AppendedData> on purpose
        failParse();
      }
      at += size;
    }
    if (document_.children.empty()) throw InputError(source_, "no XML element");
    return {std::move(document_.children.front()), appendedStart_};
  }

 private:
  static HeaderParser& self(void* data) { return *static_cast<HeaderParser*>(data); }

  static void XMLCALL onStart(void* data, const XML_Char* name, const XML_Char** attributes) {
    HeaderParser& p = self(data);
    if (p.open_.size() > kMaxDepth)
      return p.stop(fmt::format("elements nested deeper than {}", kMaxDepth));
    XmlElement element;
    element.name = name;
    for (std::size_t i = 0; attributes[i] != nullptr; i += 2) {
      element.attributes.emplace_back(attributes[i], attributes[i + 1]);
    }
    XmlElement& parent = *p.open_.back();
    parent.children.push_back(std::move(element));
    // Only the last child of an open element can be open, so pointers on the stack stay valid.
    p.open_.push_back(&parent.children.back());
    if (p.open_.back()->name == "AppendedData") p.startAppendedData();
  }

  static void XMLCALL onEnd(void* data, const XML_Char*) { self(data).open_.pop_back(); }

  static void XMLCALL onText(void* data, const XML_Char* text, int length) {
    self(data).open_.back()->text.append(text, static_cast<std::size_t>(length));
  }

  static void XMLCALL onEntityDeclaration(void* data, const XML_Char* name, int, const XML_Char*,
                                          int, const XML_Char*, const XML_Char*, const XML_Char*,
                                          const XML_Char*) {
    self(data).stop(fmt::format("the file declares an entity ({}); VTK files have none", name));
  }

  // VTK's appended data: whitespace, "_", then the blocks, which are not XML: parsing ends here.
  void startAppendedData() {
    const auto tagEnd = static_cast<std::size_t>(XML_GetCurrentByteIndex(parser_.get()) +
                                                 XML_GetCurrentByteCount(parser_.get()));
    if (bytes_.substr(0, tagEnd).ends_with("/>")) return;  // <AppendedData/>: nothing appended
    const std::size_t underscore = bytes_.find_first_not_of(" \t\r\n", tagEnd);
    if (underscore == std::string_view::npos || bytes_[underscore] != '_') {
      return stop("expected '_' at the start of <AppendedData>");
    }
    appendedStart_ = underscore + 1;
    XML_StopParser(parser_.get(), XML_FALSE);
  }

  void stop(const std::string& problem) {
    problem_ =
        fmt::format("{} (line {}, column {})", problem, XML_GetCurrentLineNumber(parser_.get()),
                    XML_GetCurrentColumnNumber(parser_.get()) + 1);
    XML_StopParser(parser_.get(), XML_FALSE);
  }

  [[noreturn]] void failParse() const {
    if (!problem_.empty()) throw InputError(source_, problem_);
    const XML_Error error = XML_GetErrorCode(parser_.get());
    const bool endsEarly = error == XML_ERROR_NO_ELEMENTS || error == XML_ERROR_UNCLOSED_TOKEN ||
                           error == XML_ERROR_PARTIAL_CHAR ||
                           error == XML_ERROR_UNCLOSED_CDATA_SECTION;
    if (endsEarly && open_.size() > 1) {
      throw InputError(source_,
                       fmt::format("the file ends inside <{}> (truncated?)", open_.back()->name));
    }
    std::string problem = XML_ErrorString(error);
    if (error == XML_ERROR_TAG_MISMATCH && open_.size() > 1) {
      problem += fmt::format(" (the open element is <{}>)", open_.back()->name);
    }
    throw InputError(source_, fmt::format("malformed XML at line {}, column {}: {}",
                                          XML_GetCurrentLineNumber(parser_.get()),
                                          XML_GetCurrentColumnNumber(parser_.get()) + 1, problem));
  }

  std::string_view bytes_;
  const std::string& source_;
  std::unique_ptr<std::remove_pointer_t<XML_Parser>, decltype(&XML_ParserFree)> parser_;
  XmlElement document_;  // holds the root element
  std::vector<XmlElement*> open_{&document_};
  std::optional<std::size_t> appendedStart_;
  std::string problem_;  // why a handler stopped the parser
};

}  // namespace

bool isXmlSpace(char c) { return c == ' ' || c == '\n' || c == '\t' || c == '\r'; }

std::string_view trimmedXmlSpace(std::string_view text) {
  while (!text.empty() && isXmlSpace(text.front())) text.remove_prefix(1);
  while (!text.empty() && isXmlSpace(text.back())) text.remove_suffix(1);
  return text;
}

std::string excerpt(std::string_view text) {
  std::string out;
  for (const char c : text.substr(0, 40)) out += (c >= ' ' && c <= '~') ? c : '?';
  if (text.size() > 40) out += "...";
  return out;
}

const std::string* XmlElement::attribute(std::string_view key) const {
  for (const auto& [k, v] : attributes) {
    if (k == key) return &v;
  }
  return nullptr;
}

std::vector<const XmlElement*> XmlElement::childrenNamed(std::string_view childName) const {
  std::vector<const XmlElement*> found;
  for (const XmlElement& c : children) {
    if (c.name == childName) found.push_back(&c);
  }
  return found;
}

const XmlElement* XmlElement::child(std::string_view childName) const {
  for (const XmlElement& c : children) {
    if (c.name == childName) return &c;
  }
  return nullptr;
}

const XmlElement* XmlElement::dataArray(std::string_view arrayName) const {
  for (const XmlElement& c : children) {
    const std::string* n = c.attribute("Name");
    if (c.name == "DataArray" && n != nullptr && *n == arrayName) return &c;
  }
  return nullptr;
}

XmlHeader parseXmlHeader(std::string_view bytes, const std::string& source) {
  return HeaderParser(bytes, source).parse();
}

}  // namespace amrstream::output
