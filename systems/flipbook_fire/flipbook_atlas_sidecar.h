#pragma once
// atlas.json, the sidecar of a flipbook atlas (flipbook_atlas.h) written by `pyro bake-flipbook
// --atlas CxR`: what a game engine needs to play the atlas (columns, rows, frame count and size,
// frames per second, the colour space, the tile order), how it was baked (scene, frames,
// loop_blend, engine version) and, when there is one, the motion-vector atlas and its encoding
// (flipbook_motion.h). The key names are docs/cli.md's.
#include <string>

#include <nlohmann/json.hpp>

#include "systems/flipbook_fire/flipbook_atlas.h"

namespace pyro {

struct AtlasSidecar {
  AtlasLayout layout;
  int frames = 0;
  double frames_per_second = 30.0;
  std::string image = "atlas.png";
  std::string color_space = "srgb";
  // How it was baked.
  std::string scene;
  int loop_blend = 0;
  std::string engine_version;
  // The motion-vector atlas: empty when the bake has none.
  std::string motion_image;
  float motion_strength = 0.0f;
  // The same atlases as OpenEXR, for linear data (empty: none): colour as linear half-float
  // RGBA, alpha premultiplied, before the shown frame's highlight roll-off; motion as R = u,
  // G = v up in frame UV per frame, exact (no bias, strength or rounding).
  std::string linear_image;
  std::string motion_linear_image;
};

nlohmann::json atlas_sidecar_json(const AtlasSidecar& sidecar);

// Reads the keys a player needs (image, columns, rows, frames, frame_width, frame_height,
// frames_per_second, color_space; motion_vectors.image and .strength when motion_vectors is
// there). Throws UserError naming `file` and the key's JSON pointer for a key that is missing or
// of the wrong type or range (frames above columns x rows, a colour space other than "srgb").
AtlasSidecar parse_atlas_sidecar(const std::string& file, const nlohmann::json& json);

}  // namespace pyro
