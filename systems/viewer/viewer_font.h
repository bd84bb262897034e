#pragma once
// The overlay's bitmap font: 5×7 glyphs drawn for this project, for the digits, capital letters
// and ASCII punctuation (lower-case letters are shown as capitals). No font files are read.
#include <array>
#include <cstdint>
#include <string>

namespace pyro {

inline constexpr int glyph_width = 5;
inline constexpr int glyph_height = 7;

// Rows top to bottom; bit 4 is the leftmost column.
using Glyph = std::array<uint8_t, glyph_height>;

// The glyph of `c`: lower case maps to upper case; a character without a glyph (control
// characters, non-ASCII bytes) gets a hollow box, which is_drawable tells apart.
const Glyph& glyph_for(char c);
bool is_drawable(char c);

}  // namespace pyro
