#include "render/image/utf8.hpp"

#include <cstdint>

namespace amrstream::render {
namespace {

bool isContinuation(unsigned char byte) { return (byte & 0xC0u) == 0x80u; }

struct Lead {
  int length;         // bytes in the sequence, 0 when `byte` cannot start one
  char32_t bits;      // the payload bits of the lead byte
  char32_t smallest;  // the smallest code point of that length (shorter is overlong)
};

Lead leadOf(unsigned char byte) {
  if (byte < 0x80u) return {1, byte, 0};
  if ((byte & 0xE0u) == 0xC0u) return {2, byte & 0x1Fu, 0x80};
  if ((byte & 0xF0u) == 0xE0u) return {3, byte & 0x0Fu, 0x800};
  if ((byte & 0xF8u) == 0xF0u) return {4, byte & 0x07u, 0x10000};
  return {0, 0, 0};
}

}  // namespace

std::u32string decodeUtf8(std::string_view text) {
  std::u32string decoded;
  decoded.reserve(text.size());
  std::size_t i = 0;
  while (i < text.size()) {
    const Lead lead = leadOf(static_cast<unsigned char>(text[i]));
    bool valid = lead.length > 0 && i + lead.length <= text.size();
    char32_t c = lead.bits;
    for (int k = 1; valid && k < lead.length; ++k) {
      const auto byte = static_cast<unsigned char>(text[i + k]);
      valid = isContinuation(byte);
      c = (c << 6) | (byte & 0x3Fu);
    }
    valid = valid && c >= lead.smallest && c <= 0x10FFFF && !(c >= 0xD800 && c <= 0xDFFF);
    decoded.push_back(valid ? c : kReplacementCharacter);
    i += valid ? static_cast<std::size_t>(lead.length) : 1;
  }
  return decoded;
}

std::string_view dropLastCodePoint(std::string_view text) {
  if (text.empty()) return text;
  std::size_t end = text.size() - 1;
  // Back over continuation bytes to the lead byte, at most three of them.
  for (int k = 0; k < 3 && end > 0 && isContinuation(static_cast<unsigned char>(text[end])); ++k)
    --end;
  return text.substr(0, end);
}

}  // namespace amrstream::render
