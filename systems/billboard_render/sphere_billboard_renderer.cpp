#include "systems/billboard_render/sphere_billboard_renderer.h"

namespace pyro {

void SphereBillboardRenderer::draw(const DrawList& list, const CameraFrame& frame,
                                   const gpu::RenderTarget& target, GLuint scene_depth,
                                   int scene_width, int scene_height, bool planar, bool sprites) {
  if (list.size() == 0) return;
  const GLuint vao = instances_.upload(list);
  target.bind();
  const gpu::Program& program = programs_.get(planar, /*shading=*/0);
  begin_sphere_billboards(program, frame, planar, scene_depth);
  const glm::ivec2 size(target.width(), target.height());
  set_sphere_billboard_depth_scale(program, size, scene_width, scene_height);
  glBindVertexArray(vao);
  draw_sphere_billboards(program, list, instances_, frame, {glm::ivec2(0), size, size}, planar, sprites);
  end_sphere_billboards();
}

}  // namespace pyro
