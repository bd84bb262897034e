#pragma once
// GPU state of spherical billboards (Umenhoffer et al. 2006): particles as spheres of a
// homogeneous medium, opacity from the real path length of each pixel's ray, clipped by the
// near plane and the opaque scene's depth; and the planar billboards they replace, for
// comparison.
#include "components/draw_list.h"
#include "engine/gpu/gl_objects.h"
#include "engine/gpu/render_target.h"
#include "engine/math/camera_math.h"
#include "systems/billboard_render/instance_buffer.h"
#include "systems/billboard_render/sphere_billboard_programs.h"

namespace pyro {

class SphereBillboardRenderer {
 public:
  // Blends the (back-to-front) particles into `target`; `scene_depth` is the opaque scene's
  // depth texture (window depth) of size scene_width x scene_height, which may be larger than
  // the target (a reduced-resolution layer). `planar`: classic billboards through the centres.
  // `sprites`: point sprites where they fit (draw_sphere_billboards), else quads throughout.
  void draw(const DrawList& list, const CameraFrame& frame, const gpu::RenderTarget& target,
            GLuint scene_depth, int scene_width, int scene_height, bool planar, bool sprites);

 private:
  SphereBillboardPrograms programs_;
  InstanceBuffer instances_;
};

}  // namespace pyro
