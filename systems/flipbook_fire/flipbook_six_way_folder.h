#pragma once
// A flipbook folder that holds six-way lightmaps (`pyro bake-flipbook --six-way`:
// six_way.json beside six_way_a/ and six_way_b/, each a folder of numbered RGBA PNG frames in
// Unity VFX Graph's packing, systems/flipbook_fire/six_way_basis.h) read into FlipbookFrames:
// lightmap A as `rgba`, lightmap B as `six_way_b`, frame i of each the same frame.
#include <string>

#include "systems/flipbook_fire/flipbook_folder.h"

namespace pyro {

// Whether `folder` holds six_way.json.
bool holds_six_way_bake(const std::string& folder);

// Throws UserError naming six_way.json and the key (unparsable, no frame count, a count the
// folders do not hold), or the lightmap folder or file (missing, unreadable, of another size
// than its pair).
FlipbookFrames read_six_way_flipbook(const std::string& folder);

}  // namespace pyro
