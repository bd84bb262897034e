#pragma once
// Makes the GpuFrame for the given settings: one scene target per view (at frame_scale of the
// output size), a layer per view when layer_scale < 1 (at least 1x1), the output target at the
// views' size (twice as wide for the side-by-side and left-right modes), and a full-size display
// target when frame_scale < 1.
#include "components/gpu_frame.h"
#include "components/render_settings.h"

namespace pyro {

int layer_extent(int full, float scale);
GpuFrame make_gpu_frame(const RenderSettings& settings);

}  // namespace pyro
