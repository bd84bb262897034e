#pragma once
// Measuring a candidate setting on this machine: its image error against the scene's ground
// truth and its time per frame.
//
// Ground truth:
//  * Gaussian particle scenes (clouds, volumes): the CPU reference (systems/runtime/reference), the
//    exact sum of Gaussians integrated in closed form, over the GL render of the opaque scene
//    (meshes and background, which both renderers share) and cut at its depth; lit media with
//    exact shadows on both (lit_particle_reference.h).
//  * Spherical or explosion-shaded particles: there is no CPU reference for them, so the truth
//    is the converged GL render: particle layers at full resolution and the finest time step
//    (4 substeps per frame). Errors are then relative to that render, not to an exact image.
#include <string>
#include <vector>

#include "systems/runtime/scene/scene_description.h"
#include "systems/runtime/quality/quality_settings.h"
#include "systems/runtime/reference/rgb_image.h"

namespace pyro {

class QualityGroundTruth {
 public:
  // Renders the truth for each frame in `frames` (ascending) at width x height (mono).
  QualityGroundTruth(const SceneDescription& scene, int width, int height, std::vector<int> frames);

  bool cpu_reference() const { return cpu_reference_; }
  std::string description() const;
  const std::vector<int>& frames() const { return frames_; }
  const RgbImage& image(size_t k) const { return images_.at(k); }
  double seconds() const { return seconds_; }

 private:
  bool cpu_reference_ = false;
  std::vector<int> frames_;
  std::vector<RgbImage> images_;
  double seconds_ = 0.0;
};

// The CPU reference images of `frames` (ascending) of a Gaussian particle scene (mono, width x
// height): the exact particles over the GL-rendered opaque scene, lit with exact shadows when the
// scene's media are lit (systems/runtime/reference/lit_particle_reference.h; fitted anisotropic particles:
// anisotropic_reference.h). A scene holding both kinds of Gaussian throws UserError naming it.
std::vector<RgbImage> particle_scene_references(const SceneDescription& scene, int width, int height,
                                                const std::vector<int>& frames);

// Whether all the scene's particles are Gaussian splats (every set's kind), which the footprint
// table shapes and the CPU reference can render.
bool gaussian_particles(const SceneDescription& scene);
// Whether the scene's particles move by integrated dynamics (emitters), so the time step matters.
bool has_dynamics(const SceneDescription& scene);

// sqrt of the mean over the truth's frames of each frame's squared RMSE (engine/math/image_error.h
// convention: RGB, clamped to [0, 1]) of the scene rendered with `q`.
double measure_rmse(const SceneDescription& scene, int width, int height, const QualitySettings& q,
                    const QualityGroundTruth& truth);

// Milliseconds per frame with `q`: the fastest of `frames` frames (after one warm-up frame),
// each timed until the GPU has finished it.
double measure_ms_per_frame(const SceneDescription& scene, int width, int height,
                            const QualitySettings& q, int frames);

}  // namespace pyro
