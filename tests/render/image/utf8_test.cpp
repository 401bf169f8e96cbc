#include "render/image/utf8.hpp"

#include <gtest/gtest.h>

namespace amrstream::render {
namespace {

TEST(Utf8TextTest, DecodesEachSequenceLength) {
  EXPECT_EQ(decodeUtf8(""), U"");
  EXPECT_EQ(decodeUtf8("temp"), U"temp");
  EXPECT_EQ(decodeUtf8("\xc2\xb5m"), U"\u00b5m");              // 2 bytes
  EXPECT_EQ(decodeUtf8("\xe2\x80\xa6"), U"\u2026");            // 3 bytes
  EXPECT_EQ(decodeUtf8("\xf0\x9f\x98\x80!"), U"\U0001F600!");  // 4 bytes
}

TEST(Utf8TextTest, EachBadByteBecomesOneReplacementCharacter) {
  const char32_t bad = kReplacementCharacter;
  EXPECT_EQ(decodeUtf8("a\x80z"), (std::u32string{U'a', bad, U'z'}));      // stray continuation
  EXPECT_EQ(decodeUtf8("\xe2\x80"), (std::u32string{bad, bad}));           // truncated
  EXPECT_EQ(decodeUtf8("\xc0\xaf"), (std::u32string{bad, bad}));           // overlong '/'
  EXPECT_EQ(decodeUtf8("\xed\xa0\x80"), (std::u32string{bad, bad, bad}));  // a surrogate
  EXPECT_EQ(decodeUtf8("\xf4\x90\x80\x80"), (std::u32string(4, bad)));     // beyond U+10FFFF
  EXPECT_EQ(decodeUtf8("\xff"), (std::u32string{bad}));
}

TEST(Utf8TextTest, DropsTheWholeLastCodePoint) {
  EXPECT_EQ(dropLastCodePoint(""), "");
  EXPECT_EQ(dropLastCodePoint("ab"), "a");
  EXPECT_EQ(dropLastCodePoint("a\xc2\xb5"), "a");
  EXPECT_EQ(dropLastCodePoint("a\xf0\x9f\x98\x80"), "a");
  EXPECT_EQ(dropLastCodePoint("a\xe2\x80"), "a");  // a truncated sequence goes whole
}

}  // namespace
}  // namespace amrstream::render
