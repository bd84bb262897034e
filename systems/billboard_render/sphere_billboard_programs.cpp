#include "systems/billboard_render/sphere_billboard_programs.h"

#include <string>

#include <glm/gtc/type_ptr.hpp>

#include "engine/gpu/shader_program.h"

namespace pyro {

const gpu::Program& SphereBillboardPrograms::get(bool planar, int shading) {
  gpu::Program& p = programs_[static_cast<size_t>((planar ? 3 : 0) + shading)];
  if (p.get() == 0)
    p = gpu::load_program("sphere_billboard.vert", "sphere_billboard.frag",
                          {std::string("PLANAR ") + (planar ? "1" : "0"),
                           "SHADING " + std::to_string(shading),
                           std::string("CELLS ") + (shading != 0 ? "1" : "0")});
  return p;
}

void begin_sphere_billboards(const gpu::Program& program, const CameraFrame& frame, bool planar,
                             GLuint scene_depth) {
  if (planar) glEnable(GL_DEPTH_TEST); else glDisable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_FALSE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  glDisable(GL_CULL_FACE);
  glUseProgram(program.get());
  auto loc = [&](const char* name) { return gpu::uniform_location(program, name); };
  glUniformMatrix4fv(loc("u_view"), 1, GL_FALSE, glm::value_ptr(frame.view));
  glUniformMatrix4fv(loc("u_projection"), 1, GL_FALSE, glm::value_ptr(frame.projection));
  glUniform4f(loc("u_projection_terms"), frame.projection[0][0], frame.projection[1][1],
              frame.projection[2][0], frame.projection[2][1]);
  glUniform1f(loc("u_near"), frame.near);
  glUniform1f(loc("u_far"), frame.far);
  glBindTextureUnit(1, scene_depth);
}

void set_sphere_billboard_target(const gpu::Program& program, const gpu::RenderTarget& target,
                                 int scene_width, int scene_height) {
  auto loc = [&](const char* name) { return gpu::uniform_location(program, name); };
  glUniform2f(loc("u_depth_scale"), static_cast<float>(scene_width) / target.width(),
              static_cast<float>(scene_height) / target.height());
  glUniform2f(loc("u_viewport"), static_cast<float>(target.width()), static_cast<float>(target.height()));
}

void end_sphere_billboards() {
  glBindVertexArray(0);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  glEnable(GL_DEPTH_TEST);
}

}  // namespace pyro
