#include "systems/flipbook_fire/flipbook_six_way_folder.h"

#include <filesystem>

#include <nlohmann/json.hpp>

#include "engine/core/user_error.h"
#include "engine/core/content_path.h"

namespace pyro {

namespace {

namespace fs = std::filesystem;

constexpr const char* kSidecar = "six_way.json";

// The frame count the sidecar states.
size_t sidecar_frames(const std::string& folder) {
  const std::string path = (fs::path(folder) / kSidecar).string();
  nlohmann::json sidecar;
  try {
    sidecar = nlohmann::json::parse(read_text_file(path));
  } catch (const nlohmann::json::exception& e) {
    throw UserError(path, "", std::string("expected a six-way sidecar in JSON: ") + e.what());
  }
  if (!sidecar.is_object() || !sidecar.contains("frames") || !sidecar["frames"].is_number_unsigned() ||
      sidecar["frames"].get<uint64_t>() == 0)
    throw UserError(path, "/frames", "expected the frame count, a positive integer");
  return sidecar["frames"].get<size_t>();
}

FlipbookFrames read_lightmap(const std::string& folder, const char* name, size_t frames) {
  const fs::path dir = fs::path(folder) / name;
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw UserError(dir.string(), "", "expected the folder of six-way lightmap frames that " +
                                          std::string(kSidecar) + " goes with, found none");
  FlipbookFrames lightmap = read_flipbook_folder(dir.string());
  if (lightmap.rgba.size() != frames)
    throw UserError((fs::path(folder) / kSidecar).string(), "/frames",
                    "expected " + std::to_string(frames) + " frames in " + dir.string() + ", found " +
                        std::to_string(lightmap.rgba.size()));
  return lightmap;
}

}  // namespace

bool holds_six_way_bake(const std::string& folder) {
  std::error_code ec;
  return fs::is_regular_file(fs::path(folder) / kSidecar, ec);
}

FlipbookFrames read_six_way_flipbook(const std::string& folder) {
  const size_t frames = sidecar_frames(folder);
  FlipbookFrames a = read_lightmap(folder, "six_way_a", frames);
  FlipbookFrames b = read_lightmap(folder, "six_way_b", frames);
  if (b.width != a.width || b.height != a.height)
    throw UserError(b.files.front(), "",
                    "expected a lightmap of " + std::to_string(a.width) + "x" + std::to_string(a.height) +
                        " pixels like six_way_a's, found " + std::to_string(b.width) + "x" +
                        std::to_string(b.height));
  a.folder = folder;
  a.six_way_b = std::move(b.rgba);
  return a;
}

}  // namespace pyro
