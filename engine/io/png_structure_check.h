#pragma once
// A structural check of a PNG file made before stb_image decodes it. stb_image trusts the chunk
// layout: a zero-length IDAT chunk makes it call memcpy with a null destination (undefined
// behaviour, found by tools/fuzz.sh png), and the size in IHDR decides how much it allocates.
// This check walks the chunk list (PNG specification, 2nd ed., §5.2–5.6: an 8-byte signature,
// then chunks of a 4-byte big-endian length, a 4-byte type of ASCII letters, the data and a
// CRC-32 of type and data) and throws UserError(path, "byte N" or the chunk, why) unless:
// - the signature is right, every chunk lies inside the file and its CRC matches;
// - IHDR comes first, is 13 bytes, and gives a size in [1, max_side] on each axis;
// - there is at least one IDAT chunk, none of them empty, and IEND ends the file.
#include <cstdint>
#include <string>
#include <vector>

namespace pyro {

// The largest width or height a PNG may declare (16384: 1 GiB of RGBA at the worst).
inline constexpr uint32_t kPngMaxSide = 16384;

struct PngHeader {
  uint32_t width = 0, height = 0;
  uint8_t bit_depth = 0, color_type = 0;
};

PngHeader check_png_structure(const std::string& path, const std::vector<uint8_t>& bytes,
                              uint32_t max_side = kPngMaxSide);

}  // namespace pyro
