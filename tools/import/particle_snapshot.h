#pragma once
// Renders a list of Gaussian particles with the real pipeline (sorting, camera and billboard
// systems on a small world, offscreen through EGL) and reads the image back: what the engine
// shows of an imported cloud, for comparison with the CPU reference. A benchmark's runtime: a
// world of its own particles (no scene file, nothing to prepare), built directly.
#include <vector>

#include "engine/particles/gaussian_particle.h"
#include "systems/runtime/reference/rgb_image.h"
#include "systems/runtime/scene/scene_description.h"
#include "systems/runtime/scene_runtime/anisotropic_snapshot.h"  // SnapshotTiming

namespace pyro {

RgbImage render_particle_snapshot(const std::vector<GaussianParticle>& particles,
                                  const CameraDescription& camera, int width, int height,
                                  const glm::vec3& background, int repeats = 1,
                                  SnapshotTiming* timing = nullptr);

}  // namespace pyro
