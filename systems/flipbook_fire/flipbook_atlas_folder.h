#pragma once
// A flipbook folder that holds an atlas (atlas.json beside atlas.png and, from a bake with motion
// vectors, motion.png; flipbook_atlas_sidecar.h) read into the same FlipbookFrames as a folder of
// the same frames: tile i of the atlas is frame i.
#include <string>

#include "systems/flipbook_fire/flipbook_folder.h"

namespace pyro {

// Whether `folder` holds atlas.json.
bool holds_flipbook_atlas(const std::string& folder);

// Throws UserError naming atlas.json and the key (a missing or bad key, an atlas image whose size
// is not columns x frame_width by rows x frame_height, a motion atlas of another size) or the
// image file (unreadable).
FlipbookFrames read_flipbook_atlas(const std::string& folder);

}  // namespace pyro
