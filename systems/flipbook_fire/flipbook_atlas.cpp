#include "systems/flipbook_fire/flipbook_atlas.h"

#include <cstring>
#include <stdexcept>

#include "engine/core/user_error.h"

namespace pyro {

namespace {

int parse_count(const std::string& text, size_t begin, size_t end) {
  if (begin >= end || end - begin > 4) return 0;
  int n = 0;
  for (size_t i = begin; i < end; ++i) {
    if (text[i] < '0' || text[i] > '9') return 0;
    n = n * 10 + (text[i] - '0');
  }
  return n;
}

// Byte offset of row y of tile `index` in the atlas.
size_t tile_row_offset(const AtlasLayout& l, int index, int y, int channels) {
  const int c = index % l.columns, r = index / l.columns;
  return ((static_cast<size_t>(r) * l.frame_height + y) * l.width() + static_cast<size_t>(c) * l.frame_width) *
         channels;
}

}  // namespace

AtlasLayout parse_atlas_grid(const std::string& text, const std::string& option) {
  const size_t x = text.find('x');
  AtlasLayout l;
  if (x != std::string::npos) {
    l.columns = parse_count(text, 0, x);
    l.rows = parse_count(text, x + 1, text.size());
  }
  if (x == std::string::npos || l.columns < 1 || l.rows < 1)
    throw UserError("command line", option,
                    "expected COLUMNSxROWS with whole numbers from 1 to 9999 (e.g. 8x8), found \"" +
                        text + "\"");
  return l;
}

namespace {

// Bytes or floats alike: each frame's rows copied into its tile, the rest left zero.
template <typename Sample>
std::vector<Sample> pack_tiles(const AtlasLayout& l, const std::vector<std::vector<Sample>>& frames,
                               int channels) {
  if (frames.size() > static_cast<size_t>(l.tiles()))
    throw std::invalid_argument("pack_atlas: more frames than tiles");
  const size_t frame_samples = static_cast<size_t>(l.frame_width) * l.frame_height * channels;
  std::vector<Sample> atlas(static_cast<size_t>(l.width()) * l.height() * channels, Sample{0});
  const size_t row_samples = static_cast<size_t>(l.frame_width) * channels;
  for (size_t i = 0; i < frames.size(); ++i) {
    if (frames[i].size() != frame_samples) throw std::invalid_argument("pack_atlas: frame of the wrong size");
    for (int y = 0; y < l.frame_height; ++y)
      std::memcpy(atlas.data() + tile_row_offset(l, static_cast<int>(i), y, channels),
                  frames[i].data() + static_cast<size_t>(y) * row_samples, row_samples * sizeof(Sample));
  }
  return atlas;
}

}  // namespace

std::vector<uint8_t> pack_atlas(const AtlasLayout& l, const std::vector<std::vector<uint8_t>>& frames,
                                int channels) {
  return pack_tiles(l, frames, channels);
}

std::vector<float> pack_atlas(const AtlasLayout& l, const std::vector<std::vector<float>>& frames,
                              int channels) {
  return pack_tiles(l, frames, channels);
}

std::vector<std::vector<uint8_t>> split_atlas(const AtlasLayout& l, const std::vector<uint8_t>& atlas,
                                              int channels, int frames) {
  if (frames > l.tiles() || atlas.size() != static_cast<size_t>(l.width()) * l.height() * channels)
    throw std::invalid_argument("split_atlas: atlas and layout disagree");
  std::vector<std::vector<uint8_t>> out(static_cast<size_t>(frames));
  for (int i = 0; i < frames; ++i) {
    std::vector<uint8_t>& frame = out[static_cast<size_t>(i)];
    const size_t row_bytes = static_cast<size_t>(l.frame_width) * channels;
    frame.resize(row_bytes * l.frame_height);
    for (int y = 0; y < l.frame_height; ++y)
      std::memcpy(frame.data() + static_cast<size_t>(y) * row_bytes,
                  atlas.data() + tile_row_offset(l, i, y, channels), row_bytes);
  }
  return out;
}

}  // namespace pyro
