#include "systems/billboard_render/sphere_billboard_renderer.h"

namespace pyro {

void SphereBillboardRenderer::draw(const DrawList& list, const CameraFrame& frame,
                                   const gpu::RenderTarget& target, GLuint scene_depth,
                                   int scene_width, int scene_height, bool planar) {
  if (list.size() == 0) return;
  const GLuint vao = instances_.upload(list);
  target.bind();
  const gpu::Program& program = programs_.get(planar, /*shading=*/0);
  begin_sphere_billboards(program, frame, planar, scene_depth);
  set_sphere_billboard_target(program, target, scene_width, scene_height);
  glBindVertexArray(vao);
  glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(list.size()));
  end_sphere_billboards();
}

}  // namespace pyro
