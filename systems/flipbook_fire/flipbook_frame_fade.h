#pragma once
// Preparing baked flame frames (Rose 2007, chapter 4: flame video is cropped, its base blacked
// out and softened before it goes on billboards): the frame is multiplied, in linear light, by
// a window that is 0 on its left, right and top borders and at its base and rises to 1 over a
// margin. Whatever crop a fire's `preparation` later takes, a flame never ends in a hard edge at
// the card's side or top, and the base of one card does not draw a bright line across the
// flames of the row below it (the bands of stacked rows).
#include <cstdint>
#include <vector>

namespace pyro {

struct FrameFade {
  float side = 0.2f;  // fraction of the width over which each side rises from 0 to 1
  float top = 0.15f;  // fraction of the height over which the top rises
  float base = 0.18f; // fraction of the height over which the bottom rises
};

// The window at pixel (x, y), y = 0 the top row: the product of s(x / (side W)),
// s((W - 1 - x) / (side W)), s(y / (top H)), s((H - 1 - y) / (base H)), s(t) = smoothstep
// 3t² − 2t³ of t clamped to [0, 1] (a margin of 0 leaves that border alone). Exactly 0 on the
// first and last column, the top row and (base > 0) the bottom row.
float frame_fade_weight(const FrameFade& fade, int width, int height, int x, int y);

// Multiplies each pixel of an RGB8 sRGB frame (rows top-down) by the window in linear light.
void apply_frame_fade(const FrameFade& fade, int width, int height, std::vector<uint8_t>& rgb);

}  // namespace pyro
