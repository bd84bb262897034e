#pragma once
// How much a frame pattern "marches" or "circles" (Rose 2007, section 4.4: with every increment
// +1 the fire appeared to move away from the viewer; with +1 / -1 in the two columns it circled
// about the vertical axis).
//
// Both are apparent motion: a flame frame shown by billboard a at step t is shown by a
// neighbouring billboard b (same group; next row in the same column, or next column in the same
// row) at step t + 1, i.e. frame_b(t + 1) = frame_a(t). Each such transfer is a unit vector
// u = (p_b - p_a) / |p_b - p_a| in the fire's base plane (lateral, depth). Over one loop of the
// flipbook (n steps; every sequence has period dividing n), with B billboards:
//   march       = |sum of u| / (n B)                       coherent translation
//   circulation = |sum of (u . t_hat)| / (n B)             coherent rotation about the axis,
//                 t_hat the unit tangent (counter-clockwise seen from above) at the transfer's
//                 midpoint, relative to the billboards' centroid
//   transfers   = number of transfers / (n B)              apparent motion of any direction
// A pattern with no coherent motion scores 0 and 0; every neighbour pair of a column all
// stepping +1 adds one transfer per step.
#include <vector>

#include "components/flipbook_fire.h"

namespace pyro {

struct PatternMotion {
  double march = 0.0;
  double circulation = 0.0;
  double transfers = 0.0;
  glm::vec2 march_direction{0.0f};  // unit (lateral, depth) of the summed transfers, or zero
};

PatternMotion measure_pattern_motion(const std::vector<FlipbookBillboard>& billboards,
                                     int frame_count);

}  // namespace pyro
