#pragma once
// A flipbook as one texture atlas: `columns` x `rows` tiles of frame_width x frame_height
// pixels, frame i in tile (c, r) = (i mod columns, i div columns), row 0 at the top of the image
// (row-major from the top left). This is the order Unity's Shader Graph Flipbook node reads with
// its default Invert Y ("flipbooks typically start from top left": docs.unity3d.com, Packages
// com.unity.shadergraph, Flipbook-Node) and Unreal's ("sub-images are ordered from
// left-to-right, top-to-bottom": dev.epicgames.com, unreal-engine, subuv-modules). Tiles beyond
// the last frame are left zero (transparent black).
#include <cstdint>
#include <string>
#include <vector>

namespace pyro {

struct AtlasLayout {
  int columns = 1, rows = 1;
  int frame_width = 0, frame_height = 0;
  int width() const { return columns * frame_width; }
  int height() const { return rows * frame_height; }
  int tiles() const { return columns * rows; }
};

// "8x8" (columns x rows) from a command-line option; UserError naming `option` otherwise.
AtlasLayout parse_atlas_grid(const std::string& text, const std::string& option);

// Packs `frames` (each frame_width x frame_height x `channels` bytes, top row first) into one
// atlas image (width() x height() x channels). std::invalid_argument when there are more frames
// than tiles or a frame has the wrong size.
std::vector<uint8_t> pack_atlas(const AtlasLayout& layout, const std::vector<std::vector<uint8_t>>& frames,
                                int channels);
// The same of float frames (linear data: an EXR atlas).
std::vector<float> pack_atlas(const AtlasLayout& layout, const std::vector<std::vector<float>>& frames,
                              int channels);

// The first `frames` tiles of `atlas` (width() x height() x channels), in frame order.
std::vector<std::vector<uint8_t>> split_atlas(const AtlasLayout& layout, const std::vector<uint8_t>& atlas,
                                              int channels, int frames);

}  // namespace pyro
