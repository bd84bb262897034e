#include "systems/flipbook_fire/flipbook_atlas_folder.h"

#include <filesystem>

#include <nlohmann/json.hpp>

#include "engine/core/user_error.h"
#include "engine/io/png_file.h"
#include "engine/core/content_path.h"
#include "systems/flipbook_fire/flipbook_atlas_sidecar.h"

namespace pyro {

namespace {

namespace fs = std::filesystem;

AtlasSidecar read_sidecar(const std::string& file) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(read_text_file(file));
  } catch (const nlohmann::json::exception& e) {
    throw UserError(file, "", std::string("expected a JSON atlas sidecar: ") + e.what());
  }
  return parse_atlas_sidecar(file, j);
}

// The atlas image named by `key`, of the sidecar's size (else a UserError naming the key).
PngImage read_atlas_image(const std::string& sidecar_file, const AtlasSidecar& s,
                          const std::string& image, const std::string& key) {
  const PngImage png = read_png((fs::path(sidecar_file).parent_path() / image).string());
  if (png.width != s.layout.width() || png.height != s.layout.height())
    throw UserError(sidecar_file, key,
                    "expected " + image + " of columns x frame_width by rows x frame_height = " +
                        std::to_string(s.layout.width()) + "x" + std::to_string(s.layout.height()) +
                        " pixels, found " + std::to_string(png.width) + "x" + std::to_string(png.height));
  return png;
}

}  // namespace

bool holds_flipbook_atlas(const std::string& folder) {
  std::error_code ec;
  return fs::is_regular_file(fs::path(folder) / "atlas.json", ec);
}

FlipbookFrames read_flipbook_atlas(const std::string& folder) {
  const std::string sidecar_file = (fs::path(folder) / "atlas.json").string();
  const AtlasSidecar s = read_sidecar(sidecar_file);
  const PngImage atlas = read_atlas_image(sidecar_file, s, s.image, "/image");
  FlipbookFrames f;
  f.folder = folder;
  f.width = s.layout.frame_width;
  f.height = s.layout.frame_height;
  f.files.push_back((fs::path(folder) / s.image).string());
  for (const std::vector<uint8_t>& tile : split_atlas(s.layout, atlas.pixels, atlas.channels, s.frames))
    f.rgba.push_back(flipbook_rgba(tile.data(), f.width, f.height, atlas.channels));
  if (s.motion_image.empty()) return f;
  const PngImage motion = read_atlas_image(sidecar_file, s, s.motion_image, "/motion_vectors/image");
  if (motion.channels != 4)
    throw UserError(sidecar_file, "/motion_vectors/image",
                    "expected " + s.motion_image + " as RGBA (R = u, G = v, B = 0, A = 1), found " +
                        std::to_string(motion.channels) + " channel(s)");
  for (const std::vector<uint8_t>& tile : split_atlas(s.layout, motion.pixels, 4, s.frames))
    f.motion.push_back(decode_motion(tile, f.width, f.height, s.motion_strength));
  return f;
}

}  // namespace pyro
