#pragma once
// The views a frame renders: the mono camera alone, or its left and right eyes.
#include <vector>

#include "components/camera.h"
#include "components/render_settings.h"
#include "components/stereo_camera.h"
#include "engine/math/camera_math.h"

namespace pyro {

CameraFrame mono_frame(const Camera& camera, const RenderSettings& settings);

// One frame for mono output; left then right for stereo (`stereo` null means default
// StereoParameters).
std::vector<CameraFrame> rendered_views(const Camera& camera, const StereoCamera* stereo,
                                        const RenderSettings& settings);

}  // namespace pyro
