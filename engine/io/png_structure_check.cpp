#include "engine/io/png_structure_check.h"

#include <array>
#include <cstring>

#include "engine/core/user_error.h"

namespace pyro {

namespace {

// CRC-32 as PNG uses it (specification, annex D: polynomial 0xEDB88320, reflected, initial and
// final XOR 0xFFFFFFFF).
const std::array<uint32_t, 256>& crc_table() {
  static const std::array<uint32_t, 256> table = [] {
    std::array<uint32_t, 256> t{};
    for (uint32_t n = 0; n < 256; ++n) {
      uint32_t c = n;
      for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      t[n] = c;
    }
    return t;
  }();
  return table;
}

uint32_t crc32(const uint8_t* data, size_t n) {
  const auto& t = crc_table();
  uint32_t c = 0xFFFFFFFFu;
  for (size_t i = 0; i < n; ++i) c = t[(c ^ data[i]) & 0xFF] ^ (c >> 8);
  return c ^ 0xFFFFFFFFu;
}

uint32_t be32(const uint8_t* p) {
  return (uint32_t(p[0]) << 24) | (uint32_t(p[1]) << 16) | (uint32_t(p[2]) << 8) | uint32_t(p[3]);
}

bool is_letter(uint8_t c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }

}  // namespace

PngHeader check_png_structure(const std::string& path, const std::vector<uint8_t>& bytes,
                              uint32_t max_side) {
  static const uint8_t kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  auto fail = [&](size_t at, const std::string& why) -> void {
    throw UserError(path, "byte " + std::to_string(at), "not a valid PNG file: " + why);
  };
  if (bytes.size() < 8 || std::memcmp(bytes.data(), kSignature, 8) != 0)
    fail(0, "the 8-byte PNG signature is missing");

  PngHeader header;
  size_t pos = 8;
  int chunks = 0, idat_chunks = 0;
  bool ended = false;
  while (pos < bytes.size()) {
    if (ended) fail(pos, "bytes after the IEND chunk");
    if (bytes.size() - pos < 12)
      fail(pos, "a chunk needs 12 bytes (length, type, CRC), only " +
                    std::to_string(bytes.size() - pos) + " remain");
    const uint32_t length = be32(&bytes[pos]);
    const uint8_t* type = &bytes[pos + 4];
    if (length > 0x7FFFFFFFu || length > bytes.size() - pos - 12)
      fail(pos, "a chunk of " + std::to_string(length) + " bytes, but only " +
                    std::to_string(bytes.size() - pos - 12) + " remain");
    for (int i = 0; i < 4; ++i)
      if (!is_letter(type[i])) fail(pos + 4, "a chunk type of four ASCII letters");
    const std::string name(reinterpret_cast<const char*>(type), 4);
    const uint32_t stored_crc = be32(&bytes[pos + 8 + length]);
    if (crc32(type, size_t(length) + 4) != stored_crc)
      fail(pos, "the CRC of chunk " + name + " does not match its contents (damaged file)");
    const uint8_t* data = type + 4;
    if (chunks == 0) {
      if (name != "IHDR") fail(pos, "IHDR as the first chunk, found " + name);
      if (length != 13) fail(pos, "an IHDR chunk of 13 bytes, found " + std::to_string(length));
      header.width = be32(data);
      header.height = be32(data + 4);
      header.bit_depth = data[8];
      header.color_type = data[9];
      if (header.width == 0 || header.height == 0 || header.width > max_side ||
          header.height > max_side)
        fail(pos + 8, "an image size in [1, " + std::to_string(max_side) + "] on each axis, found " +
                          std::to_string(header.width) + "x" + std::to_string(header.height));
    } else if (name == "IHDR") {
      fail(pos, "a single IHDR chunk");
    }
    if (name == "IDAT") {
      if (length == 0) fail(pos, "IDAT chunks with data, found an empty one");
      ++idat_chunks;
    }
    if (name == "IEND") ended = true;
    ++chunks;
    pos += size_t(length) + 12;
  }
  if (idat_chunks == 0) fail(pos, "at least one IDAT (image data) chunk, found none");
  if (!ended) fail(pos, "an IEND chunk at the end (the file is truncated)");
  return header;
}

}  // namespace pyro
