#include "systems/billboard_render/sphere_billboard_renderer.h"

#include <glm/gtc/type_ptr.hpp>

#include "engine/gpu/shader_program.h"

namespace pyro {

SphereBillboardRenderer::SphereBillboardRenderer()
    : program_(gpu::load_program("sphere_billboard.vert", "sphere_billboard.frag")) {}

void SphereBillboardRenderer::draw(const DrawList& list, const CameraFrame& frame,
                                   const gpu::RenderTarget& target, GLuint scene_depth,
                                   int scene_width, int scene_height, bool planar) {
  if (list.size() == 0) return;
  const GLuint vao = instances_.upload(list);
  target.bind();
  // Spherical: no depth test (the shader clips against the scene depth itself); planar: the
  // classic depth-tested billboard.
  if (planar) glEnable(GL_DEPTH_TEST); else glDisable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_FALSE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  glDisable(GL_CULL_FACE);
  glUseProgram(program_.get());
  auto loc = [&](const char* name) { return gpu::uniform_location(program_, name); };
  glUniformMatrix4fv(loc("u_view"), 1, GL_FALSE, glm::value_ptr(frame.view));
  glUniformMatrix4fv(loc("u_projection"), 1, GL_FALSE, glm::value_ptr(frame.projection));
  glUniform1i(loc("u_planar"), planar ? 1 : 0);
  glUniform2f(loc("u_depth_scale"), static_cast<float>(scene_width) / target.width(),
              static_cast<float>(scene_height) / target.height());
  glUniform2f(loc("u_viewport"), static_cast<float>(target.width()), static_cast<float>(target.height()));
  glUniform4f(loc("u_projection_terms"), frame.projection[0][0], frame.projection[1][1],
              frame.projection[2][0], frame.projection[2][1]);
  glUniform1f(loc("u_near"), frame.near);
  glUniform1f(loc("u_far"), frame.far);
  glBindTextureUnit(1, scene_depth);
  glBindVertexArray(vao);
  glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(list.size()));
  glBindVertexArray(0);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  glEnable(GL_DEPTH_TEST);
}

}  // namespace pyro
