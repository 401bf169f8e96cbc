#pragma once
// UTF-8 decoding for the text drawn into images.

#include <string>
#include <string_view>

namespace amrstream::render {

constexpr char32_t kReplacementCharacter = U'\uFFFD';

// The code points of `text`. Each byte that does not start a valid sequence (a stray
// continuation byte, a truncated, overlong or surrogate sequence, or one beyond U+10FFFF)
// becomes U+FFFD, and decoding goes on at the next byte.
std::u32string decodeUtf8(std::string_view text);

// `text` without its last code point; empty stays empty.
std::string_view dropLastCodePoint(std::string_view text);

}  // namespace amrstream::render
