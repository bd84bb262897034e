#include "systems/billboard_render/explosion_renderer.h"

#include <cmath>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "components/particle_medium.h"
#include "engine/gpu/gpu_pass_timer.h"
#include "engine/gpu/shader_program.h"
#include "engine/math/blackbody.h"
#include "engine/math/detail_noise.h"
#include "engine/math/phase_function.h"

namespace pyro {

void split_by_medium(const DrawList& list, std::array<DrawList, 3>& out) {
  for (DrawList& l : out) {
    l.center_radius.clear();
    l.color_density.clear();
    l.medium.clear();
  }
  for (size_t i = 0; i < list.size(); ++i) {
    const int m = static_cast<int>(list.medium[i].z);
    if (m < 0 || m > 2) continue;
    out[m].center_radius.push_back(list.center_radius[i]);
    out[m].color_density.push_back(list.color_density[i]);
    out[m].medium.push_back(list.medium[i]);
  }
}

ExplosionRenderer::ExplosionRenderer(const ExplosionShading& shading)
    : shading_(shading),
      program_(gpu::load_program("sphere_billboard.vert", "sphere_billboard.frag")) {
  // The paper's 2D phase texture over (cos theta, g), Cornette-Shanks (section 3.1's formula).
  const PhaseTable phase = make_phase_table(PhaseFunction::cornette_shanks, 128, 64);
  phase_g_min_ = static_cast<float>(phase.g_min);
  phase_g_max_ = static_cast<float>(phase.g_max);
  phase_cos_size_ = phase.cos_size;
  phase_g_size_ = phase.g_size;
  phase_ = gpu::make_texture(GL_TEXTURE_2D);
  glTextureStorage2D(phase_.get(), 1, GL_R32F, phase.cos_size, phase.g_size);
  glTextureSubImage2D(phase_.get(), 0, 0, 0, phase.cos_size, phase.g_size, GL_RED, GL_FLOAT, phase.values.data());
  // Black-body emission over the fire's range: chromaticity times luminance relative to T_max.
  const int bb_size = 128;
  const BlackbodyTable bb = make_blackbody_table(shading.fire_t_min, shading.fire_t_max, bb_size);
  std::vector<float> emitted(static_cast<size_t>(bb_size) * 3);
  const float top = bb.luminance.back() > 0.0f ? bb.luminance.back() : 1.0f;
  for (int i = 0; i < bb_size; ++i)
    for (int c = 0; c < 3; ++c)
      emitted[3 * i + c] = bb.rgb[3 * i + c] * bb.luminance[i] / top * shading.fire_emission;
  blackbody_ = gpu::make_texture(GL_TEXTURE_1D);
  glTextureStorage1D(blackbody_.get(), 1, GL_RGB32F, bb_size);
  glTextureSubImage1D(blackbody_.get(), 0, 0, bb_size, GL_RGB, GL_FLOAT, emitted.data());
  // The detail volume: periodic, so it repeats in space and loops in time.
  const DetailNoise noise = make_detail_noise(64, 4, 3, 0x5eedull);
  detail_ = gpu::make_texture(GL_TEXTURE_3D);
  glTextureStorage3D(detail_.get(), 1, GL_R16F, noise.size, noise.size, noise.size);
  glTextureSubImage3D(detail_.get(), 0, 0, 0, 0, noise.size, noise.size, noise.size, GL_RED, GL_FLOAT,
                      noise.values.data());
  for (GLuint t : {phase_.get(), blackbody_.get(), detail_.get()}) {
    glTextureParameteri(t, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(t, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  }
  for (GLuint t : {phase_.get(), blackbody_.get()}) {
    glTextureParameteri(t, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(t, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  }
  for (GLenum w : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
    glTextureParameteri(detail_.get(), w, GL_REPEAT);
}

void ExplosionRenderer::draw(const DrawList& list, const CameraFrame& frame,
                             const RenderSettings& settings, double time,
                             const std::array<std::unique_ptr<gpu::RenderTarget>, 3>& layers,
                             const gpu::RenderTarget& scene) {
  const int scene_width = scene.width(), scene_height = scene.height();
  const float clear[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  for (const auto& l : layers) glClearNamedFramebufferfv(l->framebuffer(), GL_COLOR, 0, clear);
  split_by_medium(list, split_);
  const bool planar = settings.particles == ParticleShape::planar;
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
  glUniform4f(loc("u_projection_terms"), frame.projection[0][0], frame.projection[1][1],
              frame.projection[2][0], frame.projection[2][1]);
  glUniform1f(loc("u_near"), frame.near);
  glUniform1f(loc("u_far"), frame.far);
  const glm::vec3 light = glm::normalize(glm::vec3(frame.view * glm::vec4(settings.light_direction, 0.0f)));
  glUniform3fv(loc("u_light_view"), 1, glm::value_ptr(light));
  const glm::vec3 irradiance = settings.light_color * shading_.light_irradiance;
  glUniform3fv(loc("u_light_irradiance"), 1, glm::value_ptr(irradiance));
  glUniform3fv(loc("u_ambient"), 1, glm::value_ptr(settings.ambient));
  glUniform4f(loc("u_phase_range"), phase_g_min_, phase_g_max_, static_cast<float>(phase_cos_size_),
              static_cast<float>(phase_g_size_));
  glUniform1f(loc("u_detail_frequency"), shading_.detail_frequency);
  glUniform1f(loc("u_detail_time"), static_cast<float>(std::fmod(time * shading_.detail_speed, 1.0)));
  glUniform4f(loc("u_fire"), shading_.fire_t_min, shading_.fire_t_max, shading_.fire_scale, shading_.fire_bias);
  glUniform1f(loc("u_fire_detail_range"), shading_.fire_detail_range);
  glBindTextureUnit(1, scene.depth_texture());
  glBindTextureUnit(2, phase_.get());
  glBindTextureUnit(3, blackbody_.get());
  glBindTextureUnit(4, detail_.get());
  for (int m = 0; m < 3; ++m) {
    const DrawList& l = split_[m];
    if (l.size() == 0) continue;
    // Profiling hook (no-op unless a session is active): this medium's layer, fragments counted.
    static const char* const layer_names[3] = {"dust layer", "smoke layer", "fire layer"};
    const gpu::GpuPassScope pass(layer_names[m], true);
    const gpu::RenderTarget& target = *layers[m];
    if (planar) {
      // Planar billboards are depth tested against the scene's depth, point-sampled down.
      glBlitNamedFramebuffer(scene.framebuffer(), target.framebuffer(), 0, 0, scene_width, scene_height,
                             0, 0, target.width(), target.height(), GL_DEPTH_BUFFER_BIT, GL_NEAREST);
    }
    target.bind();
    if (planar) glEnable(GL_DEPTH_TEST); else glDisable(GL_DEPTH_TEST);
    const MediumShading& s = shading_.media[m];
    glUniform1i(loc("u_shading"), m == static_cast<int>(ParticleMedium::fire) ? 2 : 1);
    glUniform1f(loc("u_albedo"), s.albedo);
    glUniform1f(loc("u_g"), s.g);
    glUniform1f(loc("u_detail_amplitude"), s.detail_amplitude);
    glUniform2f(loc("u_depth_scale"), static_cast<float>(scene_width) / target.width(),
                static_cast<float>(scene_height) / target.height());
    glUniform2f(loc("u_viewport"), static_cast<float>(target.width()), static_cast<float>(target.height()));
    const GLuint vao = instances_[m].upload(l, true);
    glBindVertexArray(vao);
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(l.size()));
  }
  glBindVertexArray(0);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  glEnable(GL_DEPTH_TEST);
}

}  // namespace pyro
