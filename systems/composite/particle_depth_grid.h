#pragma once
// The view depths over which a frame's particles can change a layer texel, per 8-pixel cell of
// the view. A texel of a media layer holds its particles clipped against one scene depth z (the
// spherical billboard's path ends at min(leave, z), Umenhoffer et al. 2006, eq. 2; a planar
// billboard, at its centre's depth, is depth tested against z), and every sphere lies between
// its centre's view depth d minus and plus its radius r. So a texel rendered against z holds
// exactly what it would hold against clamp(z, near, far), near = min(d - r) and far = max(d + r)
// over the particles whose images cover it. Two depths that clamp alike give the texel the same
// media, however far apart they are (a horizon behind the explosion, the bars of a tower with
// the smoke in front of them), and upsampling need not tell them apart
// (content/shaders/compose.frag).
//
// A cell holds the range of every particle whose screen rectangle (engine/math/projected_sphere.h),
// widened by `reach` pixels, meets the cell: with reach at least a layer texel (plus one for
// rounding), the range of a pixel's cell covers the particles of the four texels it is upsampled
// from, and the range of a texel's cell those of its neighbours.
#include <algorithm>
#include <glm/vec2.hpp>
#include <limits>
#include <vector>

#include "components/draw_list.h"
#include "engine/math/camera_math.h"

namespace pyro {

struct ParticleDepthRange {
  // View depths; near > far when no particle reaches.
  float near = std::numeric_limits<float>::max(), far = std::numeric_limits<float>::lowest();
  bool empty() const { return near > far; }
  void add(float lo, float hi) {
    near = std::min(near, lo);
    far = std::max(far, hi);
  }
};

struct ParticleDepthGrid {
  static constexpr int cell_pixels = 8;
  glm::ivec2 cells{0};                     // across and up, from the view's lower-left corner
  std::vector<ParticleDepthRange> ranges;  // row by row from the bottom
};

// Cells covering a view of `view` pixels.
glm::ivec2 particle_depth_cells(glm::ivec2 view);

// The particles of `list` seen from `camera` in a view of `view` pixels. A particle reaching
// behind the eye plane has no bounded image and widens every cell; one wholly behind it, none.
// Depths are widened by a relative 1e-4 for the rounding of the GPU's view transform.
ParticleDepthGrid particle_depth_grid(const DrawList& list, const CameraFrame& camera,
                                      glm::ivec2 view, float reach);

}  // namespace pyro
