#pragma once
// The spherical-billboard programs (content/shaders/sphere_billboard.*) and the GL state both
// spherical renderers share (SphereBillboardRenderer for plain particles, ExplosionRenderer for
// dust, smoke and fire). One program per variant — planar or spherical, the shading (0 the
// particle's colour, 1 dust or smoke, 2 fire) and the lighting (0 unlit, 1 lit by the light
// phase, 2 lit exactly: sphere_billboard.frag's LIT) — compiled on first use: on llvmpipe a branch on a
// uniform runs both sides, so each variant carries only its own fetches and arithmetic.
#include <array>
#include <optional>
#include <vector>

#include <glm/vec2.hpp>

#include "components/draw_list.h"
#include "engine/gpu/gl_objects.h"
#include "engine/gpu/render_target.h"
#include "engine/math/camera_math.h"
#include "systems/billboard_render/instance_buffer.h"

namespace pyro {

class SphereBillboardPrograms {
 public:
  const gpu::Program& get(bool planar, int shading, int lit = 0);

 private:
  std::array<gpu::Program, 18> programs_;  // index: (lit * 2 + planar) * 3 + shading
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
// The particle's point sprite, if it is drawn as one: its centre in target pixels, its side in
// pixels and its window-space depth in ndc (planar; 0 for spherical billboards, which are not
// depth tested). None unless its sphere (planar: its square) lies wholly in front of the near
// plane and the side is at most nine tenths of the largest point size. Spherical: the exact
// rectangle of the sphere's image (engine/math/projected_sphere.h), its longer side; planar: the
// square of half side r at the centre's depth.
std::optional<glm::vec4> sphere_billboard_sprite(const glm::vec3& centre_view, float radius,
                                                 const CameraFrame& frame, glm::vec2 target_size,
                                                 bool planar, float largest_point);
// Draws `list` (uploaded to `instances`, whose vertex array is bound, back to front) with
// `program` in use into `target`: each particle a point sprite where sphere_billboard_sprite
// gives one and `sprites` is on (the sprites uploaded as attribute 3), else a quad, in runs that
// keep the order. Leaves the viewport on the whole framebuffer and the scissor test off.
void draw_sphere_billboards(const gpu::Program& program, const DrawList& list,
                            InstanceBuffer& instances, const CameraFrame& frame,
                            const BillboardTarget& target, bool planar, bool sprites);
// Back to the engine's default state (depth test and writes on, no blending).
void end_sphere_billboards();

}  // namespace pyro
