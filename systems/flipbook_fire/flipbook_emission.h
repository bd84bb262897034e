#pragma once
// The light a flipbook's frames give off (components/flipbook_emission.h), worked out from the
// frames as loaded and prepared.
#include "components/flipbook_emission.h"
#include "components/flipbook_fire.h"
#include "systems/flipbook_fire/flipbook_folder.h"

namespace pyro {

// Per frame, the mean over every texel of its sRGB colour made linear, times its alpha when
// `blend` is linear-alpha (one-minus-destination ignores alpha: black is transparent). A six-way
// flipbook's: the mean of its emissive value times its alpha, grey (0 for baked smoke).
FlipbookEmission flipbook_emission(const FlipbookFrames& frames, FlipbookBlend blend);

}  // namespace pyro
