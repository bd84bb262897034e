#pragma once
// The spherical-billboard programs (content/shaders/sphere_billboard.*) and the GL state both
// spherical renderers share (SphereBillboardRenderer for plain particles, ExplosionRenderer for
// dust, smoke and fire). One program per variant — planar or spherical, and the shading (0 the
// particle's colour, 1 dust or smoke, 2 fire) — compiled on first use: on llvmpipe a branch on a
// uniform runs both sides, so each variant carries only its own fetches and arithmetic.
#include <array>

#include <glm/vec2.hpp>

#include "components/draw_list.h"
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
// Per target: the scene-depth texels per target pixel.
void set_sphere_billboard_depth_scale(const gpu::Program& program, glm::ivec2 target_size,
                                      int scene_width, int scene_height);

// Where a draw lands: `size` pixels from `origin` in a bound framebuffer of `framebuffer` pixels
// (a cell of the media atlas, or a whole target).
struct BillboardTarget {
  glm::ivec2 origin{0}, size{1}, framebuffer{1};
};
// Whether the particle (centre in view space) is drawn as a point sprite, given the largest
// point size: its sphere (planar: its square) wholly in front of the near plane, and the sprite
// at most nine tenths of the largest size (the CPU's and the GPU's float rounding apart).
bool sphere_billboard_as_sprite(const glm::vec3& centre_view, float radius, const CameraFrame& frame,
                                glm::vec2 target_size, bool planar, float largest_point);
// Draws `list` (its instances in the bound vertex array, back to front) with `program` in use
// into `target`: each particle a point sprite where sphere_billboard_as_sprite says so and
// `sprites` is on, else a quad, in runs that keep the order. Leaves the viewport on the whole
// framebuffer and the scissor test off.
void draw_sphere_billboards(const gpu::Program& program, const DrawList& list,
                            const CameraFrame& frame, const BillboardTarget& target, bool planar,
                            bool sprites);
// Back to the engine's default state (depth test and writes on, no blending).
void end_sphere_billboards();

}  // namespace pyro
