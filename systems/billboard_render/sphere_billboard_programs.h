#pragma once
// The spherical-billboard programs (content/shaders/sphere_billboard.*) and the GL state both
// spherical renderers share (SphereBillboardRenderer for plain particles, ExplosionRenderer for
// dust, smoke and fire). One program per variant — planar or spherical, and the shading (0 the
// particle's colour, 1 dust or smoke, 2 fire) — compiled on first use: on llvmpipe a branch on a
// uniform runs both sides, so each variant carries only its own fetches and arithmetic.
#include <array>

#include "engine/gpu/gl_objects.h"
#include "engine/gpu/render_target.h"
#include "engine/math/camera_math.h"

namespace pyro {

class SphereBillboardPrograms {
 public:
  const gpu::Program& get(bool planar, int shading);

 private:
  std::array<gpu::Program, 6> programs_;  // index: planar * 3 + shading
};

// Binds `program` and sets the state and uniforms of a spherical-billboard pass: premultiplied
// back-to-front blending, no depth writes, a depth test for planar billboards only (spherical
// ones clip against `scene_depth` in the shader), the camera's matrices and clip planes.
void begin_sphere_billboards(const gpu::Program& program, const CameraFrame& frame, bool planar,
                             GLuint scene_depth);
// Per target: its viewport size and the scene-depth texels per target pixel.
void set_sphere_billboard_target(const gpu::Program& program, const gpu::RenderTarget& target,
                                 int scene_width, int scene_height);
// Back to the engine's default state (depth test and writes on, no blending).
void end_sphere_billboards();

}  // namespace pyro
