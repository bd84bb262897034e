#include "systems/billboard_render/anisotropic_splat_renderer.h"

#include <algorithm>
#include <utility>

#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>

#include <tbb/parallel_sort.h>

#include "engine/gpu/shader_program.h"
#include "engine/math/anisotropic_optical_depth.h"
#include "systems/billboard_render/particle_blending.h"
#include "systems/billboard_render/scattering_uniforms.h"

namespace pyro {

std::vector<uint32_t> back_to_front_order(const std::vector<glm::vec3>& centres, const glm::vec3& eye) {
  std::vector<std::pair<double, uint32_t>> keys(centres.size());
  const glm::dvec3 e(eye);
  for (std::size_t i = 0; i < centres.size(); ++i) {
    const glm::dvec3 d = glm::dvec3(centres[i]) - e;
    keys[i] = {glm::dot(d, d), static_cast<uint32_t>(i)};
  }
  // A strict total order (farther first, then lower index): the result is the same however the
  // parallel sort splits the work.
  tbb::parallel_sort(keys.begin(), keys.end(), [](const auto& a, const auto& b) {
    return a.first != b.first ? a.first > b.first : a.second < b.second;
  });
  std::vector<uint32_t> order(keys.size());
  for (std::size_t i = 0; i < keys.size(); ++i) order[i] = keys[i].second;
  return order;
}

AnisotropicSplatRenderer::AnisotropicSplatRenderer()
    : program_(gpu::load_program("anisotropic_splat.vert", "anisotropic_splat.frag")) {}

const gpu::Program& AnisotropicSplatRenderer::lit_program() {
  if (!lit_program_) lit_program_.emplace(gpu::load_program("anisotropic_splat.vert", "anisotropic_splat.frag", {"LIT 1"}));
  return *lit_program_;
}

void AnisotropicSplatRenderer::upload(const std::vector<AnisotropicGaussian>& particles) {
  // Five vec4s per particle: centre and extinction, unit quaternion (x, y, z, w), scales, rgb,
  // emitted radiance.
  std::vector<glm::vec4> records(5 * particles.size());
  centres_.resize(particles.size());
  for (std::size_t i = 0; i < particles.size(); ++i) {
    const AnisotropicGaussian& g = particles[i];
    const glm::dquat q =
        glm::normalize(glm::dquat(g.rotation.w, g.rotation.x, g.rotation.y, g.rotation.z));
    records[5 * i] = glm::vec4(g.centre, g.extinction);
    records[5 * i + 1] = glm::vec4(float(q.x), float(q.y), float(q.z), float(q.w));
    records[5 * i + 2] = glm::vec4(g.scale, 0.0f);
    records[5 * i + 3] = glm::vec4(g.color, 0.0f);
    records[5 * i + 4] = glm::vec4(g.emission, 0.0f);
    centres_[i] = g.centre;
  }
  glNamedBufferData(records_.get(), static_cast<GLsizeiptr>(std::max<std::size_t>(records.size(), 1) * sizeof(glm::vec4)),
                    records.empty() ? nullptr : records.data(), GL_STATIC_DRAW);
}

void AnisotropicSplatRenderer::set_lighting(const AnisotropicLighting& lighting) {
  // The particles past the given depths are unshadowed by others: the buffer is zeroed, then
  // the given part copied in (no copy of the frame's depths on the CPU).
  const std::size_t given = std::min(lighting.others_depth.size(), centres_.size());
  glNamedBufferData(others_depth_.get(), static_cast<GLsizeiptr>(centres_.size() * sizeof(glm::vec4)), nullptr,
                    GL_STREAM_DRAW);
  if (given < centres_.size()) glClearNamedBufferData(others_depth_.get(), GL_RGBA32F, GL_RGBA, GL_FLOAT, nullptr);
  glNamedBufferSubData(others_depth_.get(), 0, static_cast<GLsizeiptr>(given * sizeof(glm::vec4)),
                       lighting.others_depth.data());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, others_depth_.get());
  lighting.scene->bind();
  set_scattering_uniforms(*lit_program_, lighting.self_shadow, lighting.scattering);
}

void AnisotropicSplatRenderer::draw(const CameraFrame& frame, const gpu::RenderTarget& target,
                                    const AnisotropicLighting* lighting) {
  if (centres_.empty()) return;
  const gpu::Program& program = lighting ? lit_program() : program_;
  const std::vector<uint32_t> order = back_to_front_order(centres_, frame.eye);
  glNamedBufferData(order_.get(), static_cast<GLsizeiptr>(order.size() * sizeof(uint32_t)), order.data(),
                    GL_STREAM_DRAW);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, records_.get());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, order_.get());
  target.bind();
  use_particle_blending();
  glUseProgram(program.get());
  if (lighting) set_lighting(*lighting);
  const glm::mat4 inverse_vp(glm::inverse(glm::dmat4(frame.view_projection)));
  glUniformMatrix4fv(gpu::uniform_location(program, "u_view_projection"), 1, GL_FALSE,
                     glm::value_ptr(frame.view_projection));
  glUniformMatrix4fv(gpu::uniform_location(program, "u_inverse_view_projection"), 1, GL_FALSE,
                     glm::value_ptr(inverse_vp));
  glUniform3fv(gpu::uniform_location(program, "u_eye"), 1, glm::value_ptr(frame.eye));
  glUniform2f(gpu::uniform_location(program, "u_pixel_ndc"), 2.0f / float(target.width()),
              2.0f / float(target.height()));
  float erf_coefficients[6];
  for (int k = 0; k < 6; ++k) erf_coefficients[k] = float(kErfAs7126[k]);
  glUniform1fv(gpu::uniform_location(program, "u_erf"), 6, erf_coefficients);
  glBindVertexArray(empty_vao_.get());  // no attributes: the shader pulls its instance
  glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(order.size()));
  glBindVertexArray(0);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
}

}  // namespace pyro
