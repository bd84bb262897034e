#include "systems/billboard_render/sphere_billboard_programs.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/gtc/type_ptr.hpp>

#include "engine/gpu/shader_program.h"
#include "engine/math/projected_sphere.h"

namespace pyro {

const gpu::Program& SphereBillboardPrograms::get(bool planar, int shading, int lit) {
  gpu::Program& p = programs_[static_cast<size_t>((lit * 2 + (planar ? 1 : 0)) * 3 + shading)];
  if (p.get() == 0) {
    std::vector<std::string> defines = {std::string("PLANAR ") + (planar ? "1" : "0"),
                                        "SHADING " + std::to_string(shading)};
    if (lit) defines.push_back("LIT " + std::to_string(lit));
    p = gpu::load_program("sphere_billboard.vert", "sphere_billboard.frag", defines);
  }
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

void set_sphere_billboard_depth_scale(const gpu::Program& program, glm::ivec2 target_size,
                                      int scene_width, int scene_height) {
  glUniform2f(gpu::uniform_location(program, "u_depth_scale"),
              static_cast<float>(scene_width) / target_size.x,
              static_cast<float>(scene_height) / target_size.y);
}

std::optional<glm::vec4> sphere_billboard_sprite(const glm::vec3& centre_view, float radius,
                                                 const CameraFrame& frame, glm::vec2 target_size,
                                                 bool planar, float largest_point) {
  const float depth = -centre_view.z, limit = 0.9f * largest_point;
  if (planar) {
    if (!(depth > 1.001f * frame.near)) return std::nullopt;
    const float side = std::max(frame.projection[0][0] * target_size.x,
                                frame.projection[1][1] * target_size.y) * radius / depth;
    if (!(side <= limit)) return std::nullopt;
    const glm::vec4 q = frame.projection * glm::vec4(centre_view, 1.0f);
    const glm::vec2 centre = (glm::vec2(q) / q.w * 0.5f + 0.5f) * target_size;
    return glm::vec4(centre, side, q.z / q.w);
  }
  if (!(depth - radius > 1.001f * frame.near)) return std::nullopt;
  ScreenRect rect;
  if (!projected_sphere_rect(centre_view, radius, frame.projection, target_size, rect))
    return std::nullopt;
  const float side = std::max(rect.size().x, rect.size().y);
  if (!(side <= limit)) return std::nullopt;
  return glm::vec4(rect.centre(), side, 0.0f);
}

void draw_sphere_billboards(const gpu::Program& program, const DrawList& list,
                            InstanceBuffer& instances, const CameraFrame& frame,
                            const BillboardTarget& target, bool planar, bool sprites) {
  const size_t n = list.size();
  if (n == 0) return;
  GLfloat point_range[2] = {1.0f, 1.0f};
  glGetFloatv(GL_POINT_SIZE_RANGE, point_range);
  // The viewport reaches past the framebuffer by half the largest sprite, so that no sprite that
  // overlaps the target has its centre (which decides clipping) outside it.
  const int guard = static_cast<int>(std::ceil(point_range[1] / 2.0f)) + 1;
  const glm::ivec4 viewport(-guard, -guard, target.framebuffer.x + 2 * guard,
                            target.framebuffer.y + 2 * guard);
  glViewport(viewport.x, viewport.y, viewport.z, viewport.w);
  glScissor(target.origin.x, target.origin.y, target.size.x, target.size.y);
  glEnable(GL_SCISSOR_TEST);
  glEnable(GL_PROGRAM_POINT_SIZE);
  auto loc = [&](const char* name) { return gpu::uniform_location(program, name); };
  glUniform2f(loc("u_viewport"), static_cast<float>(target.size.x), static_cast<float>(target.size.y));
  glUniform2f(loc("u_target_origin"), static_cast<float>(target.origin.x),
              static_cast<float>(target.origin.y));
  glUniform4f(loc("u_gl_viewport"), static_cast<float>(viewport.x), static_cast<float>(viewport.y),
              static_cast<float>(viewport.z), static_cast<float>(viewport.w));
  const GLint sprite_location = loc("u_sprite");
  // Each particle's sprite, or a zero side for a quad.
  std::vector<glm::vec4> sprite(n, glm::vec4(0.0f));
  for (size_t i = 0; sprites && i < n; ++i) {
    const glm::vec4& c = list.center_radius[i];
    const glm::vec3 centre = glm::vec3(frame.view * glm::vec4(glm::vec3(c), 1.0f));
    if (const auto s = sphere_billboard_sprite(centre, c.w, frame, glm::vec2(target.size), planar,
                                               point_range[1]))
      sprite[i] = *s;
  }
  instances.upload_sprites(sprite);
  auto is_sprite = [&](size_t i) { return sprite[i].z > 0.0f; };
  // Runs of one primitive, in the list's (back-to-front) order.
  size_t first = 0;
  bool run_sprite = is_sprite(0);
  for (size_t i = 1; i <= n; ++i) {
    const bool next = i < n ? is_sprite(i) : !run_sprite;
    if (i < n && next == run_sprite) continue;
    glUniform1i(sprite_location, run_sprite ? 1 : 0);
    glDrawArraysInstancedBaseInstance(run_sprite ? GL_POINTS : GL_TRIANGLE_STRIP, 0,
                                      run_sprite ? 1 : 4, static_cast<GLsizei>(i - first),
                                      static_cast<GLuint>(first));
    first = i;
    run_sprite = next;
  }
  glDisable(GL_PROGRAM_POINT_SIZE);
  glDisable(GL_SCISSOR_TEST);
  glViewport(0, 0, target.framebuffer.x, target.framebuffer.y);
}

void end_sphere_billboards() {
  glBindVertexArray(0);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  glEnable(GL_DEPTH_TEST);
}

}  // namespace pyro
