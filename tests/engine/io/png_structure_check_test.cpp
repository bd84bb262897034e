// The PNG chunk walk that runs before stb_image (engine/io/png_structure_check.h): a file the
// engine wrote passes; each kind of damage is refused with a UserError naming the file and the
// byte; read_png refuses the same files with the same message.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "engine/core/user_error.h"
#include "engine/io/png_file.h"
#include "engine/io/png_structure_check.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

std::vector<uint8_t> read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_bytes_png_structure_check(const std::string& path, const std::vector<uint8_t>& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

uint32_t be32(const uint8_t* p) {
  return (uint32_t(p[0]) << 24) | (uint32_t(p[1]) << 16) | (uint32_t(p[2]) << 8) | uint32_t(p[3]);
}

// A 5x3 RGB image written by the engine's own writer.
class PngStructure : public ::testing::Test {
 protected:
  void SetUp() override {
    path_ = (fs::temp_directory_path() / ("pyro_png_check_" + std::to_string(::getpid()) + ".png")).string();
    std::vector<uint8_t> pixels(5 * 3 * 3);
    for (size_t i = 0; i < pixels.size(); ++i) pixels[i] = static_cast<uint8_t>(i * 7);
    write_png(path_, 5, 3, 3, pixels);
    good_ = read_bytes(path_);
  }
  void TearDown() override { fs::remove(path_); }

  // The message check_png_structure gives for these bytes ("" if accepted).
  std::string refusal(const std::vector<uint8_t>& bytes) {
    try {
      check_png_structure(path_, bytes);
    } catch (const UserError& e) {
      EXPECT_EQ(e.file(), path_);
      EXPECT_NE(e.place().find("byte "), std::string::npos) << e.what();
      return e.what();
    }
    return "";
  }
  // Offset of the first chunk of this type.
  size_t chunk(const char* type) const {
    size_t pos = 8;
    while (pos + 12 <= good_.size()) {
      if (std::string(reinterpret_cast<const char*>(&good_[pos + 4]), 4) == type) return pos;
      pos += be32(&good_[pos]) + 12;
    }
    ADD_FAILURE() << "no " << type << " chunk";
    return 0;
  }

  std::string path_;
  std::vector<uint8_t> good_;
};

TEST_F(PngStructure, TheEnginesOwnPngPassesWithItsHeader) {
  const PngHeader h = check_png_structure(path_, good_);
  EXPECT_EQ(h.width, 5u);
  EXPECT_EQ(h.height, 3u);
  EXPECT_EQ(h.bit_depth, 8);
  EXPECT_EQ(h.color_type, 2);  // RGB
  const PngImage img = read_png(path_);
  EXPECT_EQ(img.width, 5);
  EXPECT_EQ(img.pixels[7], 49);
}

TEST_F(PngStructure, EachDamageIsRefusedWithItsReason) {
  std::vector<uint8_t> b = good_;
  b[1] = 'Q';
  EXPECT_NE(refusal(b).find("signature"), std::string::npos);

  b = good_;
  b[chunk("IDAT") + 9] ^= 0x40;  // one bit of image data: the CRC no longer matches
  EXPECT_NE(refusal(b).find("CRC of chunk IDAT"), std::string::npos);

  b.assign(good_.begin(), good_.end() - 12);  // IEND cut off
  EXPECT_NE(refusal(b).find("IEND"), std::string::npos);

  b.assign(good_.begin(), good_.begin() + static_cast<long>(chunk("IDAT")) + 20);  // mid-chunk
  EXPECT_NE(refusal(b).find("remain"), std::string::npos);

  b = good_;
  b.insert(b.end(), {1, 2, 3});
  EXPECT_NE(refusal(b).find("after the IEND"), std::string::npos);
}

// The fuzzer's finding: a zero-length IDAT chunk (with a valid CRC) made stb_image memcpy into a
// null pointer. It is refused before stb_image sees it.
TEST_F(PngStructure, AnEmptyIdatChunkIsRefused) {
  std::vector<uint8_t> b = good_;
  // An empty IDAT (length 0, "IDAT", CRC-32 of "IDAT" = 0x35AF061E) before the real one.
  const std::vector<uint8_t> empty = {0, 0, 0, 0, 'I', 'D', 'A', 'T', 0x35, 0xAF, 0x06, 0x1E};
  b.insert(b.begin() + static_cast<long>(chunk("IDAT")), empty.begin(), empty.end());
  EXPECT_NE(refusal(b).find("found an empty one"), std::string::npos);
  write_bytes_png_structure_check(path_, b);
  EXPECT_THROW(read_png(path_), UserError);
}

TEST_F(PngStructure, AnAbsurdSizeIsRefusedBeforeAnyAllocation) {
  std::vector<uint8_t> b = good_;
  // Width 100000: rewrite IHDR's width and its CRC (computed over type + data here).
  const size_t ihdr = chunk("IHDR");
  const uint32_t w = 100000;
  b[ihdr + 8] = uint8_t(w >> 24), b[ihdr + 9] = uint8_t(w >> 16), b[ihdr + 10] = uint8_t(w >> 8),
  b[ihdr + 11] = uint8_t(w);
  uint32_t c = 0xFFFFFFFFu;
  for (size_t i = ihdr + 4; i < ihdr + 8 + 13; ++i) {
    c ^= b[i];
    for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
  }
  c ^= 0xFFFFFFFFu;
  for (int k = 0; k < 4; ++k) b[ihdr + 21 + k] = uint8_t(c >> (24 - 8 * k));
  const std::string why = refusal(b);
  EXPECT_NE(why.find("100000x3"), std::string::npos) << why;
  EXPECT_NE(why.find("[1, 16384]"), std::string::npos) << why;
}

TEST_F(PngStructure, AMissingFileNamesItself) {
  fs::remove(path_);
  try {
    read_png(path_);
    FAIL() << "read a missing file";
  } catch (const UserError& e) {
    EXPECT_EQ(e.file(), path_);
    EXPECT_NE(std::string(e.what()).find("No such file"), std::string::npos);
  }
}

}  // namespace
}  // namespace pyro
