#pragma once
// Expands a fire's groups (components/flipbook_fire.h) into billboards: positions in the fire's
// frame, start frames and increments (Rose 2007, section 4.4), and each billboard's colour
// scale from the number of billboards overlapping it (section 4.5: "one must adjust the color
// intensity ... when extending to fires of a larger area").
#include <vector>

#include "components/flipbook_fire.h"

namespace pyro {

std::vector<FlipbookBillboard> expand_flipbook_groups(const FlipbookFire& fire);

// Number of billboards whose lateral extent [lateral - width/2, lateral + width/2] contains
// billboard k's centre line (k itself included): how many flame textures a ray through that
// line crosses.
int overlap_count(const std::vector<FlipbookBillboard>& billboards, size_t k, float width);

}  // namespace pyro
