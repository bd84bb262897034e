#include "systems/flipbook_fire/flipbook_atlas_sidecar.h"

#include <cmath>

#include "engine/core/user_error.h"

namespace pyro {

namespace {

constexpr const char* kOrder =
    "row-major from the top left: frame i in column i mod columns, row i div columns, row 0 at "
    "the top of the image (Unity's Flipbook node with Invert Y, Unreal's SubUV order)";
constexpr const char* kEncoding =
    "R = 0.5 + u * 0.5 / strength, G = 0.5 + v * 0.5 / strength, B = 0, A = 1, clamped, linear "
    "8-bit (decode: (2 c - 1) * strength); u, v: motion of the medium over one frame in frame UV "
    "units";
constexpr const char* kVAxis =
    "up: G grows toward the top of the frame (Unity's UV, origin at the bottom left); for "
    "Unreal's V-down texture space use 1 - G";

const nlohmann::json& require(const std::string& file, const nlohmann::json& object,
                              const std::string& pointer, const char* key) {
  if (!object.is_object() || !object.contains(key))
    throw UserError(file, pointer + "/" + key, "expected the key \"" + std::string(key) + "\", found none");
  return object[key];
}

int require_int(const std::string& file, const nlohmann::json& object, const char* key, int min) {
  const nlohmann::json& v = require(file, object, "", key);
  if (!v.is_number_integer() || v.get<long long>() < min || v.get<long long>() > 65536)
    throw UserError(file, std::string("/") + key,
                    "expected a whole number from " + std::to_string(min) + " to 65536, found " + v.dump());
  return v.get<int>();
}

std::string require_string(const std::string& file, const nlohmann::json& object,
                           const std::string& pointer, const char* key) {
  const nlohmann::json& v = require(file, object, pointer, key);
  if (!v.is_string() || v.get<std::string>().empty())
    throw UserError(file, pointer + "/" + key, "expected a file name or name, found " + v.dump());
  return v.get<std::string>();
}

double require_positive(const std::string& file, const nlohmann::json& object,
                        const std::string& pointer, const char* key) {
  const nlohmann::json& v = require(file, object, pointer, key);
  if (!v.is_number() || !(v.get<double>() > 0.0) || !std::isfinite(v.get<double>()))
    throw UserError(file, pointer + "/" + key, "expected a positive number, found " + v.dump());
  return v.get<double>();
}

}  // namespace

nlohmann::json atlas_sidecar_json(const AtlasSidecar& s) {
  nlohmann::json j = {{"image", s.image},
                      {"columns", s.layout.columns},
                      {"rows", s.layout.rows},
                      {"frames", s.frames},
                      {"frame_width", s.layout.frame_width},
                      {"frame_height", s.layout.frame_height},
                      {"frames_per_second", s.frames_per_second},
                      {"color_space", s.color_space},
                      {"order", kOrder},
                      {"baked", {{"scene", s.scene},
                                 {"frames", s.frames},
                                 {"loop_blend", s.loop_blend},
                                 {"engine_version", s.engine_version}}}};
  if (!s.motion_image.empty())
    j["motion_vectors"] = {{"image", s.motion_image},
                           {"strength", s.motion_strength},
                           {"encoding", kEncoding},
                           {"v_axis", kVAxis},
                           {"strength_choice", "the largest |u| or |v| of the bake (x 128/127): nothing clamps"}};
  if (!s.linear_image.empty())
    j["linear"] = {{"image", s.linear_image},
                   {"color_space", "linear"},
                   {"channels", "RGBA half float, alpha premultiplied, before the highlight roll-off"}};
  if (!s.motion_linear_image.empty() && j.contains("motion_vectors")) {
    j["motion_vectors"]["linear_image"] = s.motion_linear_image;
    j["motion_vectors"]["linear_encoding"] = "R = u, G = v up, frame UV per frame, half float, unscaled";
  }
  return j;
}

AtlasSidecar parse_atlas_sidecar(const std::string& file, const nlohmann::json& j) {
  if (!j.is_object()) throw UserError(file, "", "expected a JSON object (an atlas sidecar), found " + std::string(j.type_name()));
  AtlasSidecar s;
  s.image = require_string(file, j, "", "image");
  s.layout.columns = require_int(file, j, "columns", 1);
  s.layout.rows = require_int(file, j, "rows", 1);
  s.frames = require_int(file, j, "frames", 1);
  s.layout.frame_width = require_int(file, j, "frame_width", 1);
  s.layout.frame_height = require_int(file, j, "frame_height", 1);
  s.frames_per_second = require_positive(file, j, "", "frames_per_second");
  s.color_space = require_string(file, j, "", "color_space");
  if (s.color_space != "srgb")
    throw UserError(file, "/color_space", "expected \"srgb\" (the colour space of an 8-bit PNG atlas), found \"" + s.color_space + "\"");
  if (s.frames > s.layout.tiles())
    throw UserError(file, "/frames", "expected at most columns x rows = " + std::to_string(s.layout.tiles()) +
                                         " frames, found " + std::to_string(s.frames));
  if (j.contains("motion_vectors")) {
    const nlohmann::json& m = j["motion_vectors"];
    s.motion_image = require_string(file, m, "/motion_vectors", "image");
    s.motion_strength = static_cast<float>(require_positive(file, m, "/motion_vectors", "strength"));
    if (m.contains("linear_image")) s.motion_linear_image = require_string(file, m, "/motion_vectors", "linear_image");
  }
  if (j.contains("linear")) s.linear_image = require_string(file, j["linear"], "/linear", "image");
  return s;
}

}  // namespace pyro
