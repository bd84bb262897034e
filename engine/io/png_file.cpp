#include "engine/io/png_file.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <system_error>

#include "engine/core/user_error.h"
#include "engine/io/durable_file.h"
#include "engine/io/png_structure_check.h"
#include "engine/math/color.h"
#include "engine/math/highlight_rolloff.h"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#include <stb_image.h>
#include <stb_image_write.h>
#pragma GCC diagnostic pop

namespace pyro {

namespace {
void append_bytes(void* context, void* data, int size) {
  auto* out = static_cast<std::string*>(context);
  out->append(static_cast<const char*>(data), static_cast<size_t>(size));
}
}  // namespace

void write_png(const std::string& path, int width, int height, int channels,
               const std::vector<uint8_t>& pixels) {
  if (pixels.size() != static_cast<size_t>(width) * height * channels)
    throw std::invalid_argument("write_png: pixel count does not match the size");
  // Encoded in memory (stb's own file output ignores write and close errors), then written
  // durably: every write, the fsync, the close and the rename are checked.
  std::string encoded;
  if (!stbi_write_png_to_func(append_bytes, &encoded, width, height, channels, pixels.data(),
                              width * channels))
    throw std::runtime_error(path + ": the PNG encoder failed");
  write_file_durably(path, encoded);
}

std::vector<uint8_t> linear_rgba_to_srgb8(const std::vector<float>& rgba, int width, int height) {
  const size_t n = static_cast<size_t>(width) * height;
  std::vector<uint8_t> out(n * 3);
  for (size_t i = 0; i < n; ++i) {
    const glm::vec3 shown = roll_off_highlights({rgba[i * 4], rgba[i * 4 + 1], rgba[i * 4 + 2]});
    for (int c = 0; c < 3; ++c) out[i * 3 + c] = to_byte(linear_to_srgb(shown[c]));
  }
  return out;
}

PngImage read_png(const std::string& path) {
  std::vector<uint8_t> bytes;
  {
    std::ifstream in(path, std::ios::binary);
    std::error_code ec;
    if (!in || !std::filesystem::is_regular_file(path, ec))
      throw UserError(path, "", "cannot open PNG file: " +
                                    std::string(std::filesystem::exists(path, ec)
                                                    ? "not a readable regular file"
                                                    : "No such file or directory"));
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  // stb_image trusts the chunk layout (png_structure_check.h says what goes wrong without this).
  check_png_structure(path, bytes);
  if (bytes.size() > static_cast<size_t>(std::numeric_limits<int>::max()))
    throw UserError(path, "", "a PNG file smaller than 2 GiB");
  PngImage img;
  unsigned char* data = stbi_load_from_memory(bytes.data(), static_cast<int>(bytes.size()),
                                              &img.width, &img.height, &img.channels, 0);
  if (!data) throw UserError(path, "", std::string("cannot read PNG: ") + stbi_failure_reason());
  img.pixels.assign(data, data + static_cast<size_t>(img.width) * img.height * img.channels);
  stbi_image_free(data);
  return img;
}

}  // namespace pyro
