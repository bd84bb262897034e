#include "tools/bake/six_way_folder.h"

#include <cstdio>
#include <filesystem>

#include "engine/core/user_error.h"
#include "engine/io/png_file.h"

namespace pyro {

namespace {

PngImage read_texture(const std::string& folder, const char* texture, int frame) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%04d.png", frame);
  const std::string path = (std::filesystem::path(folder) / texture / name).string();
  if (!std::filesystem::is_regular_file(path))
    throw UserError(
        path, "",
        "expected a six-way texture of frame " + std::to_string(frame) + ", found no file");
  PngImage image = read_png(path);
  if (image.channels != 4)
    throw UserError(
        path, "",
        "expected an RGBA texture, found " + std::to_string(image.channels) + " channel(s)");
  return image;
}

}  // namespace

SixWayTextures read_six_way_frame(const std::string& folder, int frame) {
  PngImage a = read_texture(folder, "six_way_a", frame);
  PngImage b = read_texture(folder, "six_way_b", frame);
  if (a.width != b.width || a.height != b.height)
    throw UserError(folder, "six_way_b",
                    "expected textures of the size of six_way_a's (" + std::to_string(a.width) +
                        "x" + std::to_string(a.height) + ")");
  SixWayTextures t;
  t.width = a.width;
  t.height = a.height;
  t.a = std::move(a.pixels);
  t.b = std::move(b.pixels);
  return t;
}

}  // namespace pyro
