#pragma once
// A baked six-way frame read back from its bake's folder (six_way_bake.h): the two textures
// DIR/six_way_a/frame_NNNN.png and DIR/six_way_b/frame_NNNN.png.
#include <string>

#include "tools/bake/six_way_frame.h"

namespace pyro {

// Throws UserError naming the file when a texture is missing or unreadable, not RGBA, or of
// another size than its pair.
SixWayTextures read_six_way_frame(const std::string& folder, int frame);

}  // namespace pyro
