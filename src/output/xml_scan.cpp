#include "output/xml_scan.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <system_error>

#include "util/input_error.hpp"

namespace amrstream::output {
namespace {

// Deeper nesting than any VTK file has; the limit keeps a hostile file from exhausting the stack
// when the element tree is destroyed.
constexpr std::size_t kMaxDepth = 64;

void appendUtf8(std::string& out, std::uint32_t code) {
  if (code < 0x80) {
    out += static_cast<char>(code);
  } else if (code < 0x800) {
    out += static_cast<char>(0xC0 | (code >> 6));
    out += static_cast<char>(0x80 | (code & 0x3F));
  } else if (code < 0x10000) {
    out += static_cast<char>(0xE0 | (code >> 12));
    out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (code & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (code >> 18));
    out += static_cast<char>(0x80 | ((code >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (code & 0x3F));
  }
}

// The element tree of the text before the raw appended data. Positions in messages are byte
// offsets from the start of the file.
class XmlScanner {
 public:
  XmlScanner(std::string_view bytes, const std::string& source) : bytes_(bytes), source_(source) {}

  ScannedXml scan() {
    if (bytes_.starts_with("\xEF\xBB\xBF")) pos_ = 3;  // UTF-8 byte order mark
    skipSpace();
    if (pos_ == bytes_.size()) throw InputError(source_, "the file is empty");
    if (bytes_[pos_] != '<') {
      throw InputError(source_, "not an XML file (expected a VTK XML PolyData file, .vtp)");
    }
    XmlElement document;  // holds the root element
    std::vector<XmlElement*> open{&document};
    std::optional<std::size_t> appendedStart;
    while (!appendedStart) {
      const std::size_t lt = bytes_.find('<', pos_);
      addText(*open.back(), bytes_.substr(pos_, std::min(lt, bytes_.size()) - pos_));
      if (lt == std::string_view::npos) break;
      pos_ = lt;
      if (skipped("<?", "?>", "processing instruction") || skipped("<!--", "-->", "comment")) {
        continue;
      }
      if (bytes_.substr(pos_).starts_with("<![CDATA[")) {
        const std::size_t begin = pos_ + 9;
        const std::size_t end = bytes_.find("]]>", begin);
        if (end == std::string_view::npos) fail("unterminated CDATA section");
        addText(*open.back(), bytes_.substr(begin, end - begin));
        pos_ = end + 3;
        continue;
      }
      if (skipped("<!", ">", "declaration")) continue;
      if (bytes_.substr(pos_).starts_with("</")) {
        closeElement(open);
        continue;
      }
      appendedStart = openElement(open);
    }
    if (!appendedStart && open.size() > 1) {
      fail(fmt::format("the file ends inside <{}> (truncated?)", open.back()->name));
    }
    if (document.children.empty()) fail("no XML element");
    return {std::move(document.children.front()), appendedStart};
  }

 private:
  [[noreturn]] void fail(const std::string& problem) const {
    if (pos_ >= bytes_.size()) {
      throw InputError(source_,
                       fmt::format("the file ends inside a tag (truncated?): {}", problem));
    }
    throw InputError(source_, fmt::format("malformed XML at byte {}: {}", pos_, problem));
  }

  void skipSpace() {
    while (pos_ < bytes_.size() && isXmlSpace(bytes_[pos_])) ++pos_;
  }

  bool at(char c) const { return pos_ < bytes_.size() && bytes_[pos_] == c; }

  void expect(char c, std::string_view what) {
    if (!at(c)) fail(fmt::format("expected '{}' {}", c, what));
    ++pos_;
  }

  // Skips `open ... close` when the text at pos_ starts with `open`.
  bool skipped(std::string_view open, std::string_view close, std::string_view what) {
    if (!bytes_.substr(pos_).starts_with(open)) return false;
    const std::size_t end = bytes_.find(close, pos_ + open.size());
    if (end == std::string_view::npos) fail(fmt::format("unterminated {}", what));
    pos_ = end + close.size();
    return true;
  }

  static void addText(XmlElement& element, std::string_view text) {
    if (!trimmedXmlSpace(text).empty()) element.text.push_back(text);
  }

  std::string name() {
    const std::size_t begin = pos_;
    while (pos_ < bytes_.size() && !isXmlSpace(bytes_[pos_]) && bytes_[pos_] != '/' &&
           bytes_[pos_] != '>' && bytes_[pos_] != '=' && bytes_[pos_] != '<') {
      ++pos_;
    }
    if (pos_ == begin) fail("expected a name");
    return std::string(bytes_.substr(begin, pos_ - begin));
  }

  std::string unescape(std::string_view text) const {
    static const std::pair<std::string_view, char> named[] = {
        {"amp;", '&'}, {"lt;", '<'}, {"gt;", '>'}, {"quot;", '"'}, {"apos;", '\''}};
    std::string out;
    for (std::size_t i = 0; i < text.size();) {
      if (text[i] != '&') {
        out += text[i++];
        continue;
      }
      const std::string_view rest = text.substr(i + 1);
      const auto entity = std::find_if(std::begin(named), std::end(named),
                                       [&](const auto& e) { return rest.starts_with(e.first); });
      if (entity != std::end(named)) {
        out += entity->second;
        i += 1 + entity->first.size();
        continue;
      }
      const std::size_t semicolon = rest.find(';');
      std::uint32_t code = 0;
      if (rest.starts_with('#') && semicolon != std::string_view::npos) {
        const bool hex = rest.size() > 1 && rest[1] == 'x';
        const char* first = rest.data() + (hex ? 2 : 1);
        const char* last = rest.data() + semicolon;
        const auto [end, error] = std::from_chars(first, last, code, hex ? 16 : 10);
        if (error == std::errc() && end == last && first != last && code > 0 && code <= 0x10FFFF) {
          appendUtf8(out, code);
          i += 2 + semicolon;
          continue;
        }
      }
      fail(fmt::format("unknown entity in attribute value '{}'", excerpt(text)));
    }
    return out;
  }

  void closeElement(std::vector<XmlElement*>& open) {
    pos_ += 2;
    const std::string closed = name();
    skipSpace();
    expect('>', fmt::format("after </{}", closed));
    if (open.size() == 1) fail(fmt::format("</{}> closes no element", closed));
    if (open.back()->name != closed) {
      fail(fmt::format("</{}> closes <{}>", closed, open.back()->name));
    }
    open.pop_back();
  }

  // Returns the start of the appended data when the element is <AppendedData>.
  std::optional<std::size_t> openElement(std::vector<XmlElement*>& open) {
    ++pos_;
    XmlElement element;
    element.name = name();
    bool selfClosing = false;
    for (;;) {
      skipSpace();
      if (at('/')) {
        ++pos_;
        expect('>', fmt::format("after '/' in <{}", element.name));
        selfClosing = true;
        break;
      }
      if (at('>')) {
        ++pos_;
        break;
      }
      std::string key = name();
      skipSpace();
      expect('=', fmt::format("after attribute {} of <{}>", key, element.name));
      skipSpace();
      if (!at('"') && !at('\'')) fail(fmt::format("attribute {} is not quoted", key));
      const char quote = bytes_[pos_++];
      const std::size_t end = bytes_.find(quote, pos_);
      if (end == std::string_view::npos) fail(fmt::format("unterminated attribute {}", key));
      const std::string_view raw = bytes_.substr(pos_, end - pos_);
      if (raw.find('<') != std::string_view::npos) fail(fmt::format("'<' in attribute {}", key));
      if (element.attribute(key) != nullptr) fail(fmt::format("duplicate attribute {}", key));
      element.attributes.emplace_back(std::move(key), unescape(raw));
      pos_ = end + 1;
    }

    XmlElement& parent = *open.back();
    if (open.size() == 1 && !parent.children.empty()) fail("a second root element");
    if (open.size() > kMaxDepth) fail(fmt::format("elements nested deeper than {}", kMaxDepth));
    parent.children.push_back(std::move(element));
    // Only the last child of an open element can be open, so pointers on the stack stay valid.
    if (!selfClosing) open.push_back(&parent.children.back());
    if (selfClosing || open.back()->name != "AppendedData") return std::nullopt;

    // VTK's raw appended data: whitespace, "_", then the blocks.
    skipSpace();
    if (!at('_')) fail("expected '_' at the start of <AppendedData>");
    return pos_ + 1;
  }

  std::string_view bytes_;
  const std::string& source_;
  std::size_t pos_ = 0;
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

ScannedXml scanXml(std::string_view bytes, const std::string& source) {
  return XmlScanner(bytes, source).scan();
}

}  // namespace amrstream::output
