#include "systems/mesh_render/mesh_renderer.h"

#include <algorithm>
#include <string>

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "engine/gpu/shader_program.h"
#include "engine/math/color.h"

namespace pyro {

MeshRenderer::MeshRenderer()
    : program_(gpu::load_program("mesh.vert", "mesh.frag")),
      encode_program_(gpu::load_program("mesh.vert", "mesh.frag",
                                        {"SRGB_ENCODE 1", srgb_polynomial_define()})) {}

const gpu::Program& MeshRenderer::program_for(bool encode, int fire_lights) {
  if (fire_lights == 0) return encode ? encode_program_ : program_;
  gpu::Program& p = fire_programs_[{encode, fire_lights}];
  if (p.get() == 0) {
    std::vector<std::string> defines = {"FIRE_LIGHTS " + std::to_string(fire_lights)};
    if (encode) {
      defines.push_back("SRGB_ENCODE 1");
      defines.push_back(srgb_polynomial_define());
    }
    p = gpu::load_program("mesh.vert", "mesh.frag", defines);
  }
  return p;
}

const MeshRenderer::GpuMesh& MeshRenderer::mesh_for(const SharedMesh& mesh) {
  auto it = meshes_.find(mesh.id);
  if (it != meshes_.end()) return it->second;
  // Model space; the instance's placement is applied in the vertex shader.
  const MeshData& data = mesh.data;
  std::vector<float> interleaved;
  interleaved.reserve(data.positions.size() * 6);
  for (size_t i = 0; i < data.positions.size(); ++i) {
    for (int k = 0; k < 3; ++k) interleaved.push_back(data.positions[i][k]);
    for (int k = 0; k < 3; ++k) interleaved.push_back(data.normals[i][k]);
  }
  GpuMesh g;
  g.vertices = gpu::make_buffer();
  glNamedBufferStorage(g.vertices.get(), static_cast<GLsizeiptr>(interleaved.size() * sizeof(float)),
                       interleaved.data(), 0);
  g.indices = gpu::make_buffer();
  glNamedBufferStorage(g.indices.get(), static_cast<GLsizeiptr>(data.indices.size() * sizeof(uint32_t)),
                       data.indices.data(), 0);
  g.index_count = static_cast<GLsizei>(data.indices.size());
  // A sheet (the ground) is shaded on both sides (mesh.frag); a closed mesh (the tower, the
  // primitives) is wound counter-clockwise outside (engine/mesh/mesh_data.h), and culling its
  // back faces halves its rasterisation (docs/explosions.md).
  g.closed = mesh.closed;
  g.vao = gpu::make_vertex_array();
  const GLuint vao = g.vao.get();
  glVertexArrayVertexBuffer(vao, 0, g.vertices.get(), 0, 6 * sizeof(float));
  glVertexArrayElementBuffer(vao, g.indices.get());
  glEnableVertexArrayAttrib(vao, 0);
  glVertexArrayAttribFormat(vao, 0, 3, GL_FLOAT, GL_FALSE, 0);
  glVertexArrayAttribBinding(vao, 0, 0);
  glEnableVertexArrayAttrib(vao, 1);
  glVertexArrayAttribFormat(vao, 1, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float));
  glVertexArrayAttribBinding(vao, 1, 0);
  return meshes_.emplace(mesh.id, std::move(g)).first->second;
}

void MeshRenderer::release_unused(const std::vector<MeshInstance>& instances) {
  std::erase_if(meshes_, [&](const auto& entry) {
    return std::none_of(instances.begin(), instances.end(), [&](const MeshInstance& m) {
      return m.geometry && m.geometry->id == entry.first;
    });
  });
}

namespace {

// The background's alpha: 0 when the frames are transparent, so that the scene target's alpha is
// the meshes' coverage (their fragments write 1) and the composite carries it on.
float background_alpha(const RenderSettings& settings) { return settings.transparent ? 0.0f : 1.0f; }

// Everything the opaque image depends on, as numbers.
std::vector<float> draw_inputs(const std::vector<MeshInstance>& instances, const CameraFrame& frame,
                               const RenderSettings& settings, const LightBuffer& lights,
                               const gpu::RenderTarget& target, const ShadowVolume* shadows,
                               const MeshShadow* mesh_shadow) {
  std::vector<float> k;
  auto put = [&](const float* v, size_t n) { k.insert(k.end(), v, v + n); };
  put(glm::value_ptr(frame.view_projection), 16);
  // The light block, word by word (its integers as floats: counts are small).
  const LightBlock& block = lights.block();
  put(&block.ambient.x, 4);
  for (int i = 0; i < 4; ++i) k.push_back(static_cast<float>(block.counts[i]));
  put(&block.sun_toward[0].x, 4 * kMaxSuns);
  put(&block.sun_travel[0].x, 4 * kMaxSuns);
  put(&block.sun_radiance[0].x, 4 * kMaxSuns);
  put(&block.fire_position[0].x, 4 * kMaxFireLights);
  put(&block.fire_intensity[0].x, 4 * kMaxFireLights);
  put(glm::value_ptr(settings.background), 3);
  k.push_back(background_alpha(settings));
  k.push_back(static_cast<float>(target.width()));
  k.push_back(static_cast<float>(target.height()));
  k.push_back(static_cast<float>(target.format()));
  k.push_back(glIsEnabled(GL_FRAMEBUFFER_SRGB) ? 1.0f : 0.0f);  // how GL encodes the clear
  const bool shadowed = shadows && !shadows->empty();
  k.push_back(shadowed ? 1.0f : 0.0f);
  if (shadowed) {  // the version, exactly, as two halves
    k.push_back(static_cast<float>(shadows->version & 0xFFFFFFu));
    k.push_back(static_cast<float>((shadows->version >> 24) & 0xFFFFFFu));
  }
  const bool mesh_shadowed = mesh_shadow && !mesh_shadow->empty();
  k.push_back(mesh_shadowed ? 1.0f : 0.0f);
  if (mesh_shadowed) {
    k.push_back(static_cast<float>(mesh_shadow->version & 0xFFFFFFu));
    k.push_back(static_cast<float>((mesh_shadow->version >> 24) & 0xFFFFFFu));
  }
  for (const MeshInstance& m : instances) {
    const uint64_t id = m.geometry ? m.geometry->id : 0;  // exactly, as two halves
    k.push_back(static_cast<float>(id & 0xFFFFFFu));
    k.push_back(static_cast<float>((id >> 24) & 0xFFFFFFu));
    put(glm::value_ptr(m.placement.model_matrix()), 16);
    put(glm::value_ptr(m.color), 3);
  }
  return k;
}

void copy_image(GLuint from, GLuint to, const gpu::RenderTarget& target) {
  glCopyImageSubData(from, GL_TEXTURE_2D, 0, 0, 0, 0, to, GL_TEXTURE_2D, 0, 0, 0, 0,
                     target.width(), target.height(), 1);
}

}  // namespace

void MeshRenderer::draw(const std::vector<MeshInstance>& instances, const CameraFrame& frame,
                        const RenderSettings& settings, const LightBuffer& lights,
                        const gpu::RenderTarget& target, const ShadowVolume* shadows,
                        const MeshShadow* mesh_shadow) {
  std::vector<float> inputs = draw_inputs(instances, frame, settings, lights, target, shadows, mesh_shadow);
  Drawn& last = drawn_[target.serial()];
  if (last.color && last.inputs == inputs) {
    if (target.binds() != last.binds) {
      copy_image(last.color.get(), target.color_texture(), target);
      copy_image(last.depth.get(), target.depth_texture(), target);
      ++images_restored_;
    }
    leave_state(!instances.empty(), settings, target);
    last.binds = target.binds();
    return;
  }
  draw_meshes(instances, frame, settings, lights, target, shadows, mesh_shadow);
  ++meshes_drawn_;
  const glm::ivec3 shape(target.width(), target.height(), static_cast<int>(target.format()));
  if (!last.color || last.shape != shape) {
    last.shape = shape;
    last.color = gpu::make_texture(GL_TEXTURE_2D);
    glTextureStorage2D(last.color.get(), 1, target.format(), target.width(), target.height());
    last.depth = gpu::make_texture(GL_TEXTURE_2D);
    glTextureStorage2D(last.depth.get(), 1, GL_DEPTH_COMPONENT32F, target.width(), target.height());
  }
  copy_image(target.color_texture(), last.color.get(), target);
  copy_image(target.depth_texture(), last.depth.get(), target);
  last.inputs = std::move(inputs);
  last.binds = target.binds();
}

void MeshRenderer::leave_state(bool meshes, const RenderSettings& settings,
                               const gpu::RenderTarget& target) const {
  target.bind();
  glClearColor(settings.background.x, settings.background.y, settings.background.z,
               background_alpha(settings));
  glClearDepth(1.0);
  glDepthMask(GL_TRUE);
  if (!meshes) return;
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_BLEND);
  glCullFace(GL_BACK);
  glDisable(GL_CULL_FACE);
  glFrontFace(GL_CCW);
  glBindVertexArray(0);
}

void MeshRenderer::draw_meshes(const std::vector<MeshInstance>& instances,
                               const CameraFrame& frame, const RenderSettings& settings,
                               const LightBuffer& lights, const gpu::RenderTarget& target,
                               const ShadowVolume* shadows, const MeshShadow* mesh_shadow) {
  target.bind();
  glClearColor(settings.background.x, settings.background.y, settings.background.z,
               background_alpha(settings));
  glClearDepth(1.0);
  glDepthMask(GL_TRUE);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  if (instances.empty()) return;
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_BLEND);
  glCullFace(GL_BACK);
  // An sRGB target is written by the shader's own encoding, cheaper than GL's on llvmpipe
  // (engine/math/color.h, linear_to_srgb_polynomial); the clear above was encoded by GL.
  const bool encode = target.format() == GL_SRGB8_ALPHA8;
  const gpu::Program& program = program_for(encode, lights.block().counts.y);
  const GLboolean srgb_writes = glIsEnabled(GL_FRAMEBUFFER_SRGB);
  if (encode) glDisable(GL_FRAMEBUFFER_SRGB);
  glUseProgram(program.get());
  glUniformMatrix4fv(gpu::uniform_location(program, "u_view_projection"), 1, GL_FALSE,
                     glm::value_ptr(frame.view_projection));
  lights.bind();
  opacity_map_.bind(program, shadows);
  mesh_shadow_.bind(program, mesh_shadow);
  const GLint model = gpu::uniform_location(program, "u_model");
  const GLint rotation = gpu::uniform_location(program, "u_rotation");
  const GLint albedo = gpu::uniform_location(program, "u_albedo");
  release_unused(instances);
  for (const MeshInstance& m : instances) {
    if (!m.geometry) continue;
    const GpuMesh& g = mesh_for(*m.geometry);
    glUniformMatrix4fv(model, 1, GL_FALSE, glm::value_ptr(m.placement.model_matrix()));
    glUniformMatrix3fv(rotation, 1, GL_FALSE, glm::value_ptr(m.placement.rotation()));
    glUniform3fv(albedo, 1, glm::value_ptr(m.color));
    if (g.closed) {
      glEnable(GL_CULL_FACE);
      glFrontFace(m.placement.scale < 0.0f ? GL_CW : GL_CCW);  // a mirroring scale turns the winding
    } else {
      glDisable(GL_CULL_FACE);
    }
    glBindVertexArray(g.vao.get());
    glDrawElements(GL_TRIANGLES, g.index_count, GL_UNSIGNED_INT, nullptr);
  }
  glDisable(GL_CULL_FACE);
  glFrontFace(GL_CCW);
  glBindVertexArray(0);
  if (srgb_writes) glEnable(GL_FRAMEBUFFER_SRGB);
}

}  // namespace pyro
