#pragma once
// Makes the GpuFrame for the given settings: one scene target per view, a layer per view when
// layer_scale < 1 (at least 1x1), and the output target (twice as wide for the side-by-side and
// left-right modes).
#include "components/gpu_frame.h"
#include "components/render_settings.h"

namespace pyro {

int layer_extent(int full, float scale);
GpuFrame make_gpu_frame(const RenderSettings& settings);

}  // namespace pyro
