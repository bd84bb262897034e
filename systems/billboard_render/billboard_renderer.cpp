#include "systems/billboard_render/billboard_renderer.h"

#include <algorithm>
#include <chrono>

#include <glm/gtc/type_ptr.hpp>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "engine/gpu/shader_program.h"
#include "systems/billboard_render/particle_blending.h"
#include "systems/billboard_render/parallel_copy.h"

namespace pyro {

BillboardRenderer::BillboardRenderer(const FootprintTable& table)
    : table_(table),
      kernel_program_(gpu::load_program("billboard.vert", "billboard.frag")),
      trivial_program_(gpu::load_program("billboard.vert", "billboard_trivial.frag")) {
  // The kernel texture: one texel per footprint-table node (eq. 2 maps pixels to nodes),
  // sampled bilinearly between nodes and clamped at the billboard's edge.
  kernel_texture_ = gpu::make_texture(GL_TEXTURE_2D);
  glTextureStorage2D(kernel_texture_.get(), 1, GL_R32F, table_.size, table_.size);
  glTextureSubImage2D(kernel_texture_.get(), 0, 0, 0, table_.size, table_.size, GL_RED, GL_FLOAT,
                      table_.scaled.data());
  glTextureParameteri(kernel_texture_.get(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(kernel_texture_.get(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(kernel_texture_.get(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(kernel_texture_.get(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

namespace {

// Offsets of SSBO bindings must be multiples of GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT (at
// most 256 by the specification's minimum maximum).
constexpr std::size_t kBindingAlignment = 256;

std::size_t aligned(std::size_t bytes) {
  return (bytes + kBindingAlignment - 1) / kBindingAlignment * kBindingAlignment;
}

}  // namespace

namespace {

constexpr std::size_t kParticlesPerTask = 16384;

// Two vec4s per particle (centre and radius, colour and density), every pool after the one
// before, packed in parallel straight into the mapped slot.
void pack_records(const std::vector<const ParticlePool*>& pools, glm::vec4* records) {
  std::size_t first = 0;
  for (const ParticlePool* pool : pools) {
    const ParticlePool& p = *pool;
    glm::vec4* out = records + 2 * first;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, p.size(), kParticlesPerTask),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        for (std::size_t i = r.begin(); i < r.end(); ++i) {
                          out[2 * i] = {p.px[i], p.py[i], p.pz[i], p.radius[i]};
                          out[2 * i + 1] = {p.r[i], p.g[i], p.b[i], p.density[i]};
                        }
                      });
    first += p.size();
  }
}

// A gathered list's records, in its order (the order written is then 0 .. n-1).
void pack_records(const DrawList& list, glm::vec4* records, uint32_t* order) {
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, list.size(), kParticlesPerTask),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t k = r.begin(); k < r.end(); ++k) {
                        records[2 * k] = list.center_radius[k];
                        records[2 * k + 1] = list.color_density[k];
                        order[k] = static_cast<uint32_t>(k);
                      }
                    });
}

}  // namespace

void BillboardRenderer::upload(const DrawList& list, const std::vector<const ParticlePool*>& pools) {
  std::size_t particles = list.size();
  if (list.indexed()) {
    particles = 0;
    for (const ParticlePool* p : pools) particles += p->size();
  }
  const std::size_t record_bytes = aligned(2 * particles * sizeof(glm::vec4));
  const std::size_t order_bytes = list.size() * sizeof(uint32_t);
  unsigned char* slot = ring_.next(record_bytes + order_bytes);
  const auto start = std::chrono::steady_clock::now();
  auto* records = reinterpret_cast<glm::vec4*>(slot);
  auto* order = reinterpret_cast<uint32_t*>(slot + record_bytes);
  if (list.indexed()) {
    pack_records(pools, records);
    parallel_copy(order, list.order.data(), order_bytes);
  } else {
    pack_records(list, records, order);
  }
  copy_ms_ += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  bytes_ += 2 * particles * sizeof(glm::vec4) + order_bytes;
  const auto offset = static_cast<GLintptr>(ring_.offset());
  glBindBufferRange(GL_SHADER_STORAGE_BUFFER, 0, ring_.buffer(), offset,
                    static_cast<GLsizeiptr>(std::max<std::size_t>(record_bytes, 32)));
  glBindBufferRange(GL_SHADER_STORAGE_BUFFER, 1, ring_.buffer(), offset + static_cast<GLintptr>(record_bytes),
                    static_cast<GLsizeiptr>(std::max<std::size_t>(order_bytes, 4)));
}

void BillboardRenderer::draw(const DrawList& list, const std::vector<const ParticlePool*>& pools,
                             const CameraFrame& frame, const gpu::RenderTarget& target,
                             BillboardAlignment alignment, BillboardShading shading) {
  if (list.size() == 0) return;
  upload(list, pools);
  const gpu::Program& program =
      shading == BillboardShading::kernel ? kernel_program_ : trivial_program_;
  target.bind();
  use_particle_blending();
  glUseProgram(program.get());
  glUniformMatrix4fv(gpu::uniform_location(program, "u_view_projection"), 1, GL_FALSE,
                     glm::value_ptr(frame.view_projection));
  glUniform3fv(gpu::uniform_location(program, "u_right"), 1, glm::value_ptr(frame.right));
  glUniform3fv(gpu::uniform_location(program, "u_up"), 1, glm::value_ptr(frame.up));
  glUniform3fv(gpu::uniform_location(program, "u_eye"), 1, glm::value_ptr(frame.eye));
  glUniform1i(gpu::uniform_location(program, "u_face_viewpoint"),
              alignment == BillboardAlignment::viewpoint ? 1 : 0);
  const float t0 = static_cast<float>(footprint_texcoord(table_, -table_.extent));
  const float t1 = static_cast<float>(footprint_texcoord(table_, table_.extent));
  glUniform2f(gpu::uniform_location(program, "u_texcoord_bias_scale"), t0, t1 - t0);
  glBindTextureUnit(0, kernel_texture_.get());
  glBindVertexArray(empty_vao_.get());  // no attributes: the shader pulls its instance
  const auto start = std::chrono::steady_clock::now();
  glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(list.size()));
  draw_call_ms_ += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  glBindVertexArray(0);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
}

}  // namespace pyro
