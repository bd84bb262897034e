#pragma once
// The opaque scene of a view read back from its targets: the colour (linear) and the view depth
// of the geometry the particle layers were rendered against, and how far behind it the frame's
// particles reach, for measures that need to know where the scene's depth edges are and what
// they hide (engine/math/depth_edge_error.h).
#include <vector>

#include "components/draw_list.h"
#include "components/gpu_frame.h"
#include "components/view.h"

namespace pyro {

struct OpaqueView {
  int width = 0, height = 0;
  std::vector<float> rgba;        // linear RGBA, top row first
  std::vector<float> view_depth;  // top row first
  // The farthest view depth a particle whose image covers the pixel's 8-pixel cell reaches
  // (systems/composite/particle_depth_grid.h), top row first; 0 where none does.
  std::vector<float> particle_far;
};

// View `eye` of a frame whose particles are drawn into layers (EyeTargets::media_atlas or
// layer), so that the scene target holds the opaque geometry alone, with that view's draw
// list. Throws std::logic_error otherwise or when the eye does not exist.
OpaqueView read_opaque_view(const GpuFrame& frame, const View& view, const EyeDrawLists& lists,
                            size_t eye = 0);

}  // namespace pyro
