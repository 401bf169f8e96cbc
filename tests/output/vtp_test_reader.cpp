#include "vtp_test_reader.hpp"

#include <lz4.h>
#include <zlib.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <string_view>

namespace amrstream::testing {
namespace {

[[noreturn]] void fail(const std::string& what) { throw std::runtime_error("readVtp: " + what); }

std::string unescape(std::string_view text) {
  static const std::pair<std::string_view, char> entities[] = {
      {"&amp;", '&'},   {"&lt;", '<'},  {"&gt;", '>'},   {"&quot;", '"'},
      {"&apos;", '\''}, {"&#9;", '\t'}, {"&#10;", '\n'}, {"&#13;", '\r'}};
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    bool replaced = false;
    if (text[i] == '&') {
      for (const auto& [entity, c] : entities) {
        if (text.substr(i, entity.size()) == entity) {
          out += c;
          i += entity.size();
          replaced = true;
          break;
        }
      }
      if (!replaced) fail("unknown entity in '" + std::string(text) + "'");
    } else {
      out += text[i++];
    }
  }
  return out;
}

struct Tag {
  std::string name;  // "/Piece" for a closing tag
  XmlAttributes attributes;
  bool selfClosing = false;
};

// Parses `<name a="v" b='w' ...>` or `.../>`; `text` excludes the angle brackets.
Tag parseTag(std::string_view text) {
  Tag tag;
  if (!text.empty() && text.back() == '/') {
    tag.selfClosing = true;
    text.remove_suffix(1);
  }
  const auto isSpace = [](char c) { return c == ' ' || c == '\n' || c == '\t' || c == '\r'; };
  std::size_t i = 0;
  while (i < text.size() && !isSpace(text[i])) tag.name += text[i++];
  for (;;) {
    while (i < text.size() && isSpace(text[i])) ++i;
    if (i == text.size()) break;
    const std::size_t eq = text.find('=', i);
    if (eq == std::string_view::npos)
      fail("attribute without value in <" + std::string(text) + ">");
    std::string key(text.substr(i, eq - i));
    while (!key.empty() && isSpace(key.back())) key.pop_back();
    i = eq + 1;
    while (i < text.size() && isSpace(text[i])) ++i;
    if (i == text.size() || (text[i] != '"' && text[i] != '\'')) fail("unquoted attribute " + key);
    const char quote = text[i];
    const std::size_t close = text.find(quote, i + 1);
    if (close == std::string_view::npos) fail("unterminated attribute " + key);
    if (!tag.attributes.emplace(key, unescape(text.substr(i + 1, close - i - 1))).second) {
      fail("duplicate attribute " + key);
    }
    i = close + 1;
  }
  return tag;
}

std::uint64_t number(const XmlAttributes& attributes, const std::string& key) {
  const auto it = attributes.find(key);
  if (it == attributes.end()) fail("missing attribute " + key);
  std::size_t used = 0;
  const std::uint64_t value = std::stoull(it->second, &used);
  if (used != it->second.size()) fail("attribute " + key + " is not a number: " + it->second);
  return value;
}

std::uint64_t uint64At(const std::string& file, std::uint64_t at) {
  std::uint64_t value = 0;
  if (at + sizeof(value) > file.size()) fail("block header past end of file");
  std::memcpy(&value, file.data() + at, sizeof(value));
  return value;
}

std::vector<std::byte> inflated(const std::string& compressor, const char* data, std::uint64_t size,
                                std::uint64_t expected) {
  std::vector<std::byte> out(expected);
  if (compressor == "vtkZLibDataCompressor") {
    uLongf length = expected;
    Bytef dummy = 0;
    const int status = uncompress(out.empty() ? &dummy : reinterpret_cast<Bytef*>(out.data()),
                                  &length, reinterpret_cast<const Bytef*>(data), size);
    if (status != Z_OK || length != expected) fail("a zlib block does not inflate as declared");
  } else if (compressor == "vtkLZ4DataCompressor") {
    const int length = LZ4_decompress_safe(data, reinterpret_cast<char*>(out.data()),
                                           static_cast<int>(size), static_cast<int>(expected));
    if (length < 0 || std::uint64_t(length) != expected) fail("an LZ4 block does not inflate");
  } else {
    fail("unknown compressor " + compressor);
  }
  return out;
}

// Reads a compressed block (UInt64 header) starting at `begin`; returns where it ends.
std::uint64_t readCompressed(const std::string& file, std::uint64_t begin,
                             const std::string& compressor, VtpArray& array) {
  const std::uint64_t count = uint64At(file, begin);
  if (count > file.size()) fail("block count of " + array.name() + " larger than the file");
  for (std::uint64_t i = 0; i < 3 + count; ++i) {
    array.blockHeader.push_back(uint64At(file, begin + 8 * i));
  }
  const std::uint64_t blockSize = array.blockHeader[1];
  const std::uint64_t last = array.blockHeader[2];
  std::uint64_t at = begin + 8 * (3 + count);
  for (std::uint64_t block = 0; block < count; ++block) {
    const std::uint64_t size = array.blockHeader[3 + block];
    if (at + size > file.size()) fail("block of " + array.name() + " past end of file");
    const std::uint64_t expected = block + 1 == count && last != 0 ? last : blockSize;
    const std::vector<std::byte> bytes = inflated(compressor, file.data() + at, size, expected);
    array.bytes.insert(array.bytes.end(), bytes.begin(), bytes.end());
    at += size;
  }
  return at;
}

}  // namespace

int VtpArray::components() const {
  const auto it = attributes.find("NumberOfComponents");
  return it == attributes.end() ? 1 : std::stoi(it->second);
}

const VtpArray& VtpFile::array(const std::string& section, const std::string& name) const {
  for (const VtpArray& a : arrays) {
    if (a.section == section && a.name() == name) return a;
  }
  fail("no array " + section + "/" + name);
}

VtpFile readVtp(const std::filesystem::path& path) {
  std::ifstream stream(path, std::ios::binary);
  if (!stream) fail("cannot open " + path.string());
  const std::string file{std::istreambuf_iterator<char>(stream), std::istreambuf_iterator<char>()};

  // Everything up to the "_" that opens the raw data is XML text.
  const std::size_t appendedTag = file.find("<AppendedData");
  if (appendedTag == std::string::npos) fail("no <AppendedData>");
  const std::size_t appendedTagEnd = file.find('>', appendedTag);
  const std::size_t underscore = file.find('_', appendedTagEnd);
  if (underscore == std::string::npos) fail("no '_' opening the appended data");
  if (file.find_first_not_of(" \n\t\r", appendedTagEnd + 1) != underscore) {
    fail("text between <AppendedData> and '_'");
  }
  const std::size_t base = underscore + 1;

  VtpFile vtp;
  std::vector<std::string> open;
  std::vector<std::pair<VtpArray, std::uint64_t>> pending;  // array and its block offset
  for (std::size_t at = file.find('<'); at < underscore; at = file.find('<', at)) {
    const std::size_t end = file.find('>', at);
    if (end == std::string::npos || end > underscore) fail("unterminated tag");
    const std::string_view body = std::string_view(file).substr(at + 1, end - at - 1);
    at = end + 1;
    if (body.starts_with('?') || body.starts_with('!')) continue;
    const Tag tag = parseTag(body);
    if (tag.name.starts_with('/')) {
      if (open.empty() || open.back() != tag.name.substr(1)) fail("mismatched " + tag.name);
      open.pop_back();
      continue;
    }
    if (tag.name == "VTKFile") vtp.vtkFile = tag.attributes;
    if (tag.name == "Piece") vtp.piece = tag.attributes;
    if (tag.name == "PointData") vtp.pointData = tag.attributes;
    if (tag.name == "DataArray" || tag.name == "Array") {
      if (open.empty()) fail("DataArray outside a section");
      if (tag.attributes.count("format") == 0 || tag.attributes.at("format") != "appended") {
        fail("DataArray not in appended format");
      }
      VtpArray array{open.back(), tag.attributes, {}, {}};
      pending.emplace_back(std::move(array), number(tag.attributes, "offset"));
    }
    if (!tag.selfClosing) open.push_back(tag.name);
  }
  if (open != std::vector<std::string>{"VTKFile", "AppendedData"}) fail("unbalanced tags");

  std::sort(pending.begin(), pending.end(),
            [](const auto& a, const auto& b) { return a.second < b.second; });
  std::uint64_t blocksEnd = base;
  const auto compressor = vtp.vtkFile.find("compressor");
  for (auto& [array, offset] : pending) {
    if (base + offset < blocksEnd) fail("block of " + array.name() + " overlaps the previous one");
    std::uint64_t end = 0;
    if (compressor != vtp.vtkFile.end()) {
      end = readCompressed(file, base + offset, compressor->second, array);
    } else {
      const std::uint64_t size = uint64At(file, base + offset);
      const std::uint64_t begin = base + offset + sizeof(size);
      if (begin + size > file.size()) fail("block of " + array.name() + " past end of file");
      const auto* data = reinterpret_cast<const std::byte*>(file.data()) + begin;
      array.bytes.assign(data, data + size);
      end = begin + size;
    }
    blocksEnd = std::max(blocksEnd, end);
    vtp.arrays.push_back(std::move(array));
  }
  const std::size_t close = file.find_first_not_of(" \n\t\r", blocksEnd);
  if (close == std::string::npos ||
      std::string_view(file).substr(close).find("</AppendedData>") != 0) {
    fail("appended data not followed by </AppendedData>");
  }
  return vtp;
}

}  // namespace amrstream::testing
