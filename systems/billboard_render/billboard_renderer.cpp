#include "systems/billboard_render/billboard_renderer.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/gtc/type_ptr.hpp>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "engine/gpu/shader_program.h"
#include "engine/math/gaussian_line_integral.h"
#include "engine/math/thick_particle.h"
#include "systems/billboard_render/particle_blending.h"
#include "systems/billboard_render/parallel_copy.h"
#include "systems/billboard_render/scattering_uniforms.h"

namespace pyro {

BillboardRenderer::BillboardRenderer(const FootprintTable& table)
    : table_(table),
      kernel_program_(gpu::load_program("billboard.vert", "billboard.frag")),
      trivial_program_(gpu::load_program("billboard.vert", "billboard_trivial.frag")),
      lit_program_(gpu::load_program("billboard.vert", "billboard.frag", {"LIT 1"})),
      scattering_program_(gpu::load_program("billboard.vert", "billboard.frag", {"LIT 2"})) {
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

// With lit media: each particle's others' depth (components/particle_light.h), pool after pool;
// zero for a pool without light.
void pack_shadow(const std::vector<const ParticlePool*>& pools, const SplatLighting& lighting,
                 glm::vec4* out) {
  for (std::size_t set = 0; set < pools.size(); ++set) {
    const ParticlePool& p = *pools[set];
    const ParticleLight* light = set < lighting.lights.size() ? lighting.lights[set] : nullptr;
    if (light && light->others_depth.size() == p.size())
      parallel_copy(out, light->others_depth.data(), p.size() * sizeof(glm::vec4));
    else
      std::fill(out, out + p.size(), glm::vec4(0.0f));
    out += p.size();
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

// Every pool's ids, one after another (the GPU order's tie-break).
void copy_ids(const std::vector<const ParticlePool*>& pools, uint32_t* ids) {
  for (const ParticlePool* p : pools) {
    parallel_copy(ids, p->id.data(), p->size() * sizeof(uint32_t));
    ids += p->size();
  }
}

// Whether a particle is thick (engine/math/thick_particle.h; billboard.frag, THICK_PARTICLES).
bool any_thick(const std::vector<const ParticlePool*>& pools) {
  for (const ParticlePool* p : pools)
    if (std::any_of(p->density.begin(), p->density.end(), thick_particle)) return true;
  return false;
}

std::size_t particles_in(const std::vector<const ParticlePool*>& pools) {
  std::size_t particles = 0;
  for (const ParticlePool* p : pools) particles += p->size();
  return particles;
}

}  // namespace

void BillboardRenderer::upload(const DrawList& list, const std::vector<const ParticlePool*>& pools,
                               const SplatLighting* lighting) {
  const bool from_pools = list.indexed() || list.on_gpu;
  const std::size_t particles = from_pools ? particles_in(pools) : list.size();
  const std::size_t record_bytes = aligned(2 * particles * sizeof(glm::vec4));
  // The order, or for the GPU to make it, the particles' ids.
  const std::size_t order_bytes = (list.on_gpu ? particles : list.size()) * sizeof(uint32_t);
  // Lit pools: their others' depths after the order (a gathered list is never lit).
  const bool lit = lighting && from_pools;
  const std::size_t shadow_bytes = lit ? particles * sizeof(glm::vec4) : 0;
  unsigned char* slot = ring_.next(record_bytes + (lit ? aligned(order_bytes) : order_bytes) + shadow_bytes);
  const auto start = std::chrono::steady_clock::now();
  auto* records = reinterpret_cast<glm::vec4*>(slot);
  auto* order = reinterpret_cast<uint32_t*>(slot + record_bytes);
  if (list.on_gpu) {
    pack_records(pools, records);
    copy_ids(pools, order);
  } else if (list.indexed()) {
    pack_records(pools, records);
    parallel_copy(order, list.order.data(), order_bytes);
  } else {
    pack_records(list, records, order);
  }
  const std::size_t shadow_offset = record_bytes + aligned(order_bytes);
  if (lit) pack_shadow(pools, *lighting, reinterpret_cast<glm::vec4*>(slot + shadow_offset));
  thick_ = lit && any_thick(pools);
  copy_ms_ += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  bytes_ += 2 * particles * sizeof(glm::vec4) + order_bytes + shadow_bytes;
  const auto offset = static_cast<GLintptr>(ring_.offset());
  uploaded_records_ = {ring_.buffer(), offset, static_cast<GLsizeiptr>(std::max<std::size_t>(record_bytes, 32))};
  uploaded_order_ = {ring_.buffer(), offset + static_cast<GLintptr>(record_bytes),
                     static_cast<GLsizeiptr>(std::max<std::size_t>(order_bytes, 4))};
  uploaded_records_.bind(GL_SHADER_STORAGE_BUFFER, 0);
  uploaded_order_.bind(GL_SHADER_STORAGE_BUFFER, 1);
  if (!lit) return;
  uploaded_shadow_ = {ring_.buffer(), offset + static_cast<GLintptr>(shadow_offset),
                      static_cast<GLsizeiptr>(std::max<std::size_t>(shadow_bytes, 16))};
  uploaded_shadow_.bind(GL_SHADER_STORAGE_BUFFER, 2);
}

const gpu::Program& BillboardRenderer::lit_program(const SplatLighting& lighting) const {
  const bool fire = lighting.scene->block().counts.y > 0;
  const bool scattering = fire || !(lighting.scattering == SunScattering{});
  if (lighting.sunlight == SplatSunlight::fragments) {
    if (!thick_) return scattering ? scattering_program_ : lit_program_;
    std::optional<gpu::Program>& thick = scattering ? scattering_thick_program_ : lit_thick_program_;
    if (!thick)
      thick.emplace(gpu::load_program("billboard.vert", "billboard.frag", {scattering ? "LIT 2" : "LIT 1", "THICK_PARTICLES 1"}));
    return *thick;
  }
  std::optional<gpu::Program>& program = scattering ? scattering_vertex_program_ : lit_vertex_program_;
  if (!program)
    program.emplace(gpu::load_program("billboard.vert", "billboard.frag",
                                      {scattering ? "LIT 2" : "LIT 1", "SUNLIGHT_AT_VERTICES 1"}));
  return *program;
}

void BillboardRenderer::set_lighting_uniforms(const SplatLighting& lighting) {
  const gpu::Program& program = lit_program(lighting);
  lighting.scene->bind();
  set_scattering_uniforms(program, lighting.self_shadow, lighting.scattering);
  std::array<float, kTailPolynomialTerms> tail;
  for (size_t k = 0; k < tail.size(); ++k) tail[k] = float(tail_polynomial_[k]);
  glUniform1fv(gpu::uniform_location(program, "u_tail_polynomial"), GLsizei(tail.size()), tail.data());
  if (lighting.sunlight == SplatSunlight::fragments && thick_) sunlight_map_.bind(program, lighting.map);
}

void BillboardRenderer::order_on_gpu(const DrawList& list, const std::vector<const ParticlePool*>& pools) {
  if (!gpu_sort_) gpu_sort_ = std::make_unique<GpuDepthSort>();
  GpuParticles in;
  in.records = uploaded_records_;
  in.ids = uploaded_order_;
  in.set_starts.push_back(0);
  for (const ParticlePool* p : pools) in.set_starts.push_back(in.set_starts.back() + uint32_t(p->size()));
  in.layout = gpu_key_layout(pools);
  gpu_sort_->order(in, *list.gpu_request);
}

double BillboardRenderer::time_gpu_order(const DrawList& list, const std::vector<const ParticlePool*>& pools) {
  if (!list.gpu_request) throw std::invalid_argument("time_gpu_order: the list has no GPU order request");
  DrawList ids_only;
  ids_only.on_gpu = true;
  ids_only.gpu_request = list.gpu_request;
  upload(ids_only, pools);
  order_on_gpu(ids_only, pools);  // warm-up: the driver may finish compiling on first use
  glFinish();
  const auto start = std::chrono::steady_clock::now();
  order_on_gpu(ids_only, pools);
  glFinish();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

uint32_t BillboardRenderer::gpu_kept() const { return gpu_sort_ ? gpu_sort_->read_kept() : 0; }

void BillboardRenderer::draw(const DrawList& list, const std::vector<const ParticlePool*>& pools,
                             const CameraFrame& frame, const gpu::RenderTarget& target,
                             BillboardAlignment alignment, BillboardShading shading,
                             const SplatLighting* lighting) {
  if ((list.on_gpu ? particles_in(pools) : list.size()) == 0) return;
  const bool lit = lighting && shading == BillboardShading::kernel && (list.indexed() || list.on_gpu);
  upload(list, pools, lit ? lighting : nullptr);
  if (list.on_gpu) {
    order_on_gpu(list, pools);
    glBindBufferRange(GL_SHADER_STORAGE_BUFFER, 1, gpu_sort_->order_buffer(), 0, gpu_sort_->order_bytes());
    if (lit) uploaded_shadow_.bind(GL_SHADER_STORAGE_BUFFER, 2);  // the sort's shaders bind 2 too
  }
  const gpu::Program& program =
      lit ? lit_program(*lighting) : shading == BillboardShading::kernel ? kernel_program_ : trivial_program_;
  target.bind();
  use_particle_blending();
  glUseProgram(program.get());
  if (lit) set_lighting_uniforms(*lighting);
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
  glUniform2ui(gpu::uniform_location(program, "u_order_stride_offset"),
               list.on_gpu ? GpuDepthSort::kOrderStride : 1u, list.on_gpu ? GpuDepthSort::kOrderOffset : 0u);
  if (list.on_gpu) {
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, gpu_sort_->command_buffer());
    glDrawArraysIndirect(GL_TRIANGLE_STRIP, nullptr);
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
  } else {
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(list.size()));
  }
  draw_call_ms_ += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  glBindVertexArray(0);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
}

}  // namespace pyro
