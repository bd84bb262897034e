#pragma once
// Colour quantisation for 256-colour images (GIF): one palette made from the pixels of every
// frame of a clip, and each pixel mapped to its nearest palette colour.
//
// The palette: the clip's colours in a histogram of 6 bits per channel (each cell keeps the mean
// of the colours that fell in it, so nothing is rounded to the cell), cut greedily into boxes
// (Wu 1991, "Efficient Statistical Computations for Optimal Color Quantization", Graphics Gems
// II: the box with the largest sum of squared errors is split at the plane, along its widest
// channel, that minimises the two halves' summed squared errors), then refined by Lloyd's
// k-means iterations over the cells (Lloyd 1982): each palette colour moves to the weighted mean
// of the cells nearest to it. The mapping: the nearest palette colour in squared RGB distance,
// exact, found by a search pruned on the green channel and remembered in a cache.
// Deterministic: the same pixels give the same palette and indices.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace pyro {

using PaletteColor = std::array<uint8_t, 3>;  // R, G, B

// Counts colours: RGB pixels (3 bytes each), any number of calls, then palette().
class PaletteBuilder {
 public:
  PaletteBuilder();
  void add_pixels(const uint8_t* rgb, size_t pixels);
  // At most `colors` (1..256) colours; fewer when the pixels hold fewer distinct cells.
  // Empty when no pixel was added.
  std::vector<PaletteColor> palette(int colors = 256) const;

 private:
  struct Cell {
    uint64_t count = 0;
    uint64_t sum[3] = {0, 0, 0};
  };
  std::vector<Cell> cells_;  // 2^18: 6 bits of each channel
};

// The nearest colour of a palette (1..256 colours) to any RGB colour.
class PaletteMapper {
 public:
  explicit PaletteMapper(std::vector<PaletteColor> palette);
  // The index into the palette of the colour nearest to (r, g, b) (the lowest index on a tie).
  uint8_t index_of(uint8_t r, uint8_t g, uint8_t b);
  // Indices for `pixels` RGB pixels (3 bytes each, or `stride` bytes apart).
  void map(const uint8_t* rgb, size_t pixels, uint8_t* indices, size_t stride = 3);
  const std::vector<PaletteColor>& palette() const { return palette_; }

 private:
  uint8_t search(uint8_t r, uint8_t g, uint8_t b) const;

  std::vector<PaletteColor> palette_;
  std::vector<uint8_t> by_green_;  // palette indices in ascending green
  std::vector<uint64_t> cache_;  // direct-mapped: (colour + 1) << 8 | index; 0: empty
};

}  // namespace pyro
