// The overlay's 5×7 bitmap font: every printable ASCII character has its own glyph.
#include "systems/viewer/viewer_font.h"

#include <gtest/gtest.h>

#include <map>

namespace pyro {
namespace {

int lit(const Glyph& g) {
  int n = 0;
  for (uint8_t row : g) {
    EXPECT_EQ(row & ~0x1fu, 0u) << "a row wider than 5 pixels";
    for (int b = 0; b < 5; ++b) n += (row >> b) & 1;
  }
  return n;
}

TEST(ViewerFont, EveryPrintableCharacterHasADistinctGlyph) {
  std::map<Glyph, char> seen;
  for (int c = 33; c < 127; ++c) {
    if (c >= 'a' && c <= 'z') continue;  // shown as capitals
    ASSERT_TRUE(is_drawable(char(c))) << char(c);
    const Glyph& g = glyph_for(char(c));
    EXPECT_GT(lit(g), 0) << char(c);
    const auto [it, fresh] = seen.emplace(g, char(c));
    EXPECT_TRUE(fresh) << "'" << char(c) << "' looks like '" << it->second << "'";
  }
  EXPECT_TRUE(is_drawable(' '));
  EXPECT_EQ(lit(glyph_for(' ')), 0);
}

TEST(ViewerFont, LowerCaseIsShownAsCapitalsAndUnknownBytesAsABox) {
  for (char c = 'a'; c <= 'z'; ++c) EXPECT_EQ(glyph_for(c), glyph_for(char(c - 'a' + 'A'))) << c;
  EXPECT_FALSE(is_drawable('\t'));
  EXPECT_FALSE(is_drawable(char(0xC3)));
  const Glyph& box = glyph_for('\t');
  EXPECT_EQ(box[0], 0x1f);
  EXPECT_EQ(box[6], 0x1f);
  for (int r = 1; r < 6; ++r) EXPECT_EQ(box[size_t(r)], 0x11);
  EXPECT_EQ(glyph_for(char(0xC3)), box);
  // A few glyphs checked pixel by pixel.
  EXPECT_EQ(glyph_for('1'), (Glyph{0x04, 0x0c, 0x04, 0x04, 0x04, 0x04, 0x0e}));
  EXPECT_EQ(glyph_for('-'), (Glyph{0, 0, 0, 0x1f, 0, 0, 0}));
  EXPECT_EQ(glyph_for('H'), (Glyph{0x11, 0x11, 0x11, 0x1f, 0x11, 0x11, 0x11}));
}

}  // namespace
}  // namespace pyro
