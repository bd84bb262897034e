#include "systems/billboard_render/explosion_renderer.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>

#include "components/particle_medium.h"
#include "engine/gpu/gpu_pass_timer.h"
#include "engine/gpu/shader_program.h"
#include "engine/math/blackbody.h"
#include "engine/math/detail_noise.h"

namespace pyro {

void split_by_medium(const DrawList& list, std::array<DrawList, 3>& out) {
  for (DrawList& l : out) {
    l.center_radius.clear();
    l.color_density.clear();
    l.medium.clear();
    l.light.clear();
  }
  const bool lit = list.light.size() == list.size();
  for (size_t i = 0; i < list.size(); ++i) {
    const int m = static_cast<int>(list.medium[i].z);
    if (m < 0 || m > 2) continue;
    out[m].center_radius.push_back(list.center_radius[i]);
    out[m].color_density.push_back(list.color_density[i]);
    out[m].medium.push_back(list.medium[i]);
    if (lit) out[m].light.push_back(list.light[i]);
  }
}

ExplosionRenderer::ExplosionRenderer(const ExplosionShading& shading)
    : shading_(shading) {
  // Black-body emission over the fire's range: chromaticity times luminance relative to T_max.
  const int bb_size = 128;
  const std::vector<float> emitted =
      blackbody_emission_table(shading.fire_t_min, shading.fire_t_max, shading.fire_emission, bb_size).rgb;
  blackbody_ = gpu::make_texture(GL_TEXTURE_1D);
  glTextureStorage1D(blackbody_.get(), 1, GL_RGB32F, bb_size);
  glTextureSubImage1D(blackbody_.get(), 0, 0, bb_size, GL_RGB, GL_FLOAT, emitted.data());
  // The detail volume: periodic, so it repeats in space and loops in time; the shader reads
  // its slice at the frame's time (upload_detail_slice).
  detail_volume_ = make_detail_noise(64, 4, 3, 0x5eedull);
  detail_ = gpu::make_texture(GL_TEXTURE_2D);
  glTextureStorage2D(detail_.get(), 1, GL_RG16F, detail_volume_.size, detail_volume_.size);
  for (GLuint t : {blackbody_.get(), detail_.get()}) {
    glTextureParameteri(t, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(t, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  }
  glTextureParameteri(blackbody_.get(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  for (GLenum w : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T})
    glTextureParameteri(detail_.get(), w, GL_REPEAT);
}

void ExplosionRenderer::upload_detail_slice(double time) {
  const float t = static_cast<float>(std::fmod(time * shading_.detail_speed, 1.0));
  if (t == detail_time_) return;  // the second eye of a stereo frame
  detail_time_ = t;
  const std::vector<float> slice = detail_noise_slice_rg(detail_volume_, t);
  glTextureSubImage2D(detail_.get(), 0, 0, 0, detail_volume_.size, detail_volume_.size, GL_RG,
                      GL_FLOAT, slice.data());
}

namespace {

// `data` into `buffer` (grown when too small) at binding `binding` of the storage buffers.
void upload_storage(const std::vector<glm::vec4>& data, GLuint binding, gpu::Buffer& buffer, GLsizeiptr& capacity) {
  const GLsizeiptr bytes = static_cast<GLsizeiptr>(std::max<size_t>(data.size(), 2) * sizeof(glm::vec4));
  if (buffer.get() == 0 || bytes > capacity) {
    buffer = gpu::make_buffer();
    glNamedBufferStorage(buffer.get(), bytes, nullptr, GL_DYNAMIC_STORAGE_BIT);
    capacity = bytes;
  }
  if (!data.empty())
    glNamedBufferSubData(buffer.get(), 0, static_cast<GLsizeiptr>(data.size() * sizeof(glm::vec4)), data.data());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, buffer.get());
}

glm::vec4 view_position_radius(const CameraFrame& frame, const PointEmitter& e) {
  return glm::vec4(glm::vec3(frame.view * glm::vec4(glm::vec3(e.position), 1.0f)), float(e.radius));
}

}  // namespace

void ExplosionRenderer::upload_casters(const DrawList& list, const CameraFrame& frame) {
  std::vector<glm::vec4> casters;
  casters.reserve(2 * list.size());
  for (size_t i = 0; i < list.size(); ++i) {
    const glm::vec4& c = list.center_radius[i];
    casters.push_back(glm::vec4(glm::vec3(frame.view * glm::vec4(glm::vec3(c), 1.0f)), c.w));
    casters.push_back({std::max(list.color_density[i].w, 0.0f) * list.medium[i].y, 0.0f, 0.0f, 0.0f});
  }
  upload_storage(casters, 5, casters_, casters_bytes_);
}

void ExplosionRenderer::upload_fire_emitters(const FireLights* fire, const CameraFrame& frame) {
  std::vector<glm::vec4> emitters;
  if (fire)
    for (const PointEmitter& e : fire->emitters) {
      emitters.push_back(view_position_radius(frame, e));
      emitters.push_back(glm::vec4(glm::vec3(e.intensity), 0.0f));
    }
  upload_storage(emitters, 6, emitters_, emitters_bytes_);
}

void ExplosionRenderer::draw(const DrawList& list, const CameraFrame& frame,
                             const RenderSettings& settings, const LightBuffer& lights,
                             double time, const gpu::RenderTarget& atlas, int cell_width,
                             const gpu::RenderTarget& scene, MediaLighting media_lighting,
                             const FireLights* fire, const MeshShadow* mesh_shadow) {
  const int scene_width = scene.width(), scene_height = scene.height();
  const float clear[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  glClearNamedFramebufferfv(atlas.framebuffer(), GL_COLOR, 0, clear);
  split_by_medium(list, split_);
  upload_detail_slice(time);
  if (media_lighting == MediaLighting::light_phase && list.light.size() != list.size())
    media_lighting = MediaLighting::unlit;  // no light phase ran for these particles
  if (media_lighting == MediaLighting::exact) {
    upload_casters(list, frame);
    upload_fire_emitters(fire, frame);
  }
  const bool planar = settings.particles == ParticleShape::planar;
  if (planar) {
    // Planar billboards are depth tested against the scene's depth, point-sampled down into
    // each cell.
    for (int m = 0; m < 3; ++m)
      glBlitNamedFramebuffer(scene.framebuffer(), atlas.framebuffer(), 0, 0, scene_width,
                             scene_height, m * cell_width, 0, (m + 1) * cell_width, atlas.height(),
                             GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  }
  atlas.bind();
  lights.bind();
  for (int m = 0; m < 3; ++m) {
    const DrawList& l = split_[m];
    if (l.size() == 0) continue;
    // Profiling hook (no-op unless profiling): this medium's layer, fragments counted.
    static const char* const layer_names[3] = {"dust layer", "smoke layer", "fire layer"};
    const gpu::GpuPassScope pass(layer_names[m], true);
    // One program per medium kind: fire (shading 2) or dust and smoke (1), which are lit.
    const bool is_fire = m == static_cast<int>(ParticleMedium::fire);
    const gpu::Program& program =
        programs_.get(planar, is_fire ? 2 : 1, is_fire ? 0 : static_cast<int>(media_lighting));
    begin_sphere_billboards(program, frame, planar, scene.depth_texture());
    auto loc = [&](const char* name) { return gpu::uniform_location(program, name); };
    const glm::ivec2 cell(cell_width, atlas.height());
    set_sphere_billboard_depth_scale(program, cell, scene_width, scene_height);
    glUniform1f(loc("u_light_scale"), shading_.light_irradiance);
    glUniform1f(loc("u_detail_frequency"), shading_.detail_frequency);
    glUniform4f(loc("u_fire"), shading_.fire_t_min, shading_.fire_t_max, shading_.fire_scale, shading_.fire_bias);
    glUniform1f(loc("u_fire_detail_range"), shading_.fire_detail_range);
    glBindTextureUnit(3, blackbody_.get());
    glBindTextureUnit(4, detail_.get());
    const MediumShading& s = shading_.media[m];
    glUniform1f(loc("u_albedo"), s.albedo);
    glUniform1f(loc("u_g"), s.g);
    glUniform1f(loc("u_detail_amplitude"), s.detail_amplitude);
    if (!is_fire && media_lighting == MediaLighting::exact) {
      glUniform1i(loc("u_caster_count"), static_cast<GLint>(list.size()));
      glUniform1i(loc("u_fire_emitter_count"), fire ? static_cast<GLint>(fire->emitters.size()) : 0);
      mesh_shadow_.bind(program, mesh_shadow, glm::inverse(frame.view));
    }
    const GLuint vao = instances_[m].upload(l, true);
    glBindVertexArray(vao);
    // Each medium in its cell of the atlas (the scissor keeps it there).
    draw_sphere_billboards(program, l, instances_[m], frame, {glm::ivec2(m * cell_width, 0), cell, {atlas.width(), atlas.height()}},
                           planar, settings.billboard_sprites);
  }
  end_sphere_billboards();
}

}  // namespace pyro
