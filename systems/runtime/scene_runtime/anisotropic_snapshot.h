#pragma once
// Renders a list of anisotropic Gaussian particles offscreen (the process's headless EGL context,
// systems/billboard_render/anisotropic_splat_renderer.h) over a uniform background and reads the
// image back: what the engine shows of an anisotropic cloud, for comparison with the CPU
// reference (systems/runtime/reference/anisotropic_reference.h). The target is RGBA32F, so the image
// carries no rounding beyond the shader's float arithmetic.
#include <vector>

#include "engine/particles/anisotropic_gaussian.h"
#include "systems/runtime/reference/rgb_image.h"
#include "systems/runtime/scene/scene_description.h"

namespace pyro {

struct SnapshotTiming {
  double render_seconds = 0.0;  // the frame (sort + draw + readback), best of `repeats`
};

// `timing`, when given, receives the best of `repeats` frames (upload, sort, draw and readback).
// The program is built on the first call and kept for the process.
RgbImage render_anisotropic_snapshot(const std::vector<AnisotropicGaussian>& particles,
                                     const CameraDescription& camera, int width, int height,
                                     const glm::vec3& background, int repeats = 1,
                                     SnapshotTiming* timing = nullptr);

}  // namespace pyro
