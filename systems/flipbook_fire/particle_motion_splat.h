#pragma once
// Exact motion vectors of a baked flipbook frame, from the simulation's own particles: each
// particle's screen-space motion over one frame, (project(p + v dt) - project(p)) through the
// bake camera's own projection (project_to_pixels, engine/math/camera_math.h: the renderer's
// view-projection), in frame UV units, splatted over its projected footprint and averaged per
// pixel, weighted by the particle's opacity times density times the footprint kernel
//   k(d) = (1 - d^2 / R^2)^2 for d < R,  R = radius f / depth  (f: the focal length in pixels),
// so that each pixel gets the motion of the medium that covers it. Pixels no particle covers
// take the motion of the nearest covered ones, dilated outward one pixel per pass (8-connected
// mean), for `dilation` passes (then 0): the motion-vector blend samples a frame at
// uv - t m(uv), so the pixels just ahead of the flame must carry its motion for the flame to be
// moved into them.
#include <vector>

#include <glm/vec3.hpp>

#include "engine/math/camera_math.h"
#include "systems/flipbook_fire/flipbook_motion.h"

namespace pyro {

struct MotionParticle {
  glm::vec3 position{0.0f};
  glm::vec3 velocity{0.0f};  // world units per second
  float radius = 0.0f;
  float weight = 1.0f;       // opacity x density
};

// Sums of weight x motion and of weight per pixel: frames mix (the loop's cross-fade) by adding
// scaled sums.
struct MotionSums {
  int width = 0, height = 0;
  std::vector<double> weighted_uv;  // 2 per pixel
  std::vector<double> weight;       // 1 per pixel
  MotionSums(int w, int h);
  void add(const MotionSums& other, double scale);
  MotionField field(int dilation = 16) const;
};

// Splats `particles` seen by `camera` (whose width and height may differ from the sums': pixel
// coordinates are scaled to the sums' size) over a frame of `dt` seconds into `sums`.
void splat_particle_motion(const std::vector<MotionParticle>& particles, const CameraFrame& camera,
                           float dt, MotionSums& sums);

}  // namespace pyro
