#include "systems/flipbook_fire/flipbook_renderer.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "engine/core/user_error.h"
#include "engine/gpu/shader_program.h"

namespace pyro {

namespace {
constexpr int kFloatsPerVertex = 10;  // position (3), u, v, layer, intensity, next layer, blend, motion scale

gpu::Texture motion_texture(const FlipbookFrames& frames) {
  gpu::Texture t = gpu::make_texture(GL_TEXTURE_2D_ARRAY);
  glTextureStorage3D(t.get(), 1, GL_RG16F, frames.width, frames.height,
                     static_cast<GLsizei>(frames.motion.size()));
  for (size_t layer = 0; layer < frames.motion.size(); ++layer)
    glTextureSubImage3D(t.get(), 0, 0, 0, static_cast<GLint>(layer), frames.width, frames.height, 1, GL_RG,
                        GL_FLOAT, frames.motion[layer].uv.data());
  glTextureParameteri(t.get(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(t.get(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(t.get(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(t.get(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return t;
}

// The frames as a mipmapped RGBA8 array: sRGB-encoded colour, or linear lightmap values.
gpu::Texture frame_array(const std::vector<std::vector<uint8_t>>& layers, int width, int height,
                         GLenum internal_format) {
  const int levels = 1 + static_cast<int>(std::floor(std::log2(std::max(width, height))));
  gpu::Texture t = gpu::make_texture(GL_TEXTURE_2D_ARRAY);
  glTextureStorage3D(t.get(), levels, internal_format, width, height, static_cast<GLsizei>(layers.size()));
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  for (size_t layer = 0; layer < layers.size(); ++layer)
    glTextureSubImage3D(t.get(), 0, 0, 0, static_cast<GLint>(layer), width, height, 1, GL_RGBA,
                        GL_UNSIGNED_BYTE, layers[layer].data());
  glGenerateTextureMipmap(t.get());
  glTextureParameteri(t.get(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTextureParameteri(t.get(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(t.get(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(t.get(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return t;
}

}  // namespace

FlipbookRenderer::FlipbookRenderer()
    : program_(gpu::load_program("flipbook.vert", "flipbook.frag")),
      buffer_(gpu::make_buffer()),
      vao_(gpu::make_vertex_array()) {
  const GLuint vao = vao_.get();
  const GLint sizes[4] = {3, 3, 1, 3};
  const GLuint offsets[4] = {0, 3 * sizeof(float), 6 * sizeof(float), 7 * sizeof(float)};
  for (GLuint a = 0; a < 4; ++a) {
    glEnableVertexArrayAttrib(vao, a);
    glVertexArrayAttribFormat(vao, a, sizes[a], GL_FLOAT, GL_FALSE, offsets[a]);
    glVertexArrayAttribBinding(vao, a, 0);
  }
}

int FlipbookRenderer::add_flipbook(const FlipbookFrames& frames) {
  if (frames.rgba.empty() || frames.width <= 0 || frames.height <= 0)
    throw std::invalid_argument("FlipbookRenderer::add_flipbook: no frames");
  GLint max_size = 0, max_layers = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
  glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &max_layers);
  if (frames.width > max_size || frames.height > max_size ||
      frames.rgba.size() > static_cast<size_t>(max_layers)) {
    throw UserError(frames.folder, "",
                    "expected at most " + std::to_string(max_layers) + " frames of at most " +
                        std::to_string(max_size) + " pixels a side (this OpenGL's limits), found " +
                        std::to_string(frames.rgba.size()) + " frames of " +
                        std::to_string(frames.width) + "x" + std::to_string(frames.height));
  }
  const GLenum format = frames.six_way() ? GL_RGBA8 : GL_SRGB8_ALPHA8;
  gpu::Texture t = frame_array(frames.rgba, frames.width, frames.height, format);
  Flipbook book{std::move(t), {}, false, {}, false};
  if (frames.six_way()) {
    book.six_way_b = frame_array(frames.six_way_b, frames.width, frames.height, GL_RGBA8);
    book.six_way = true;
  }
  if (frames.motion.size() == frames.rgba.size()) {
    book.motion = motion_texture(frames);
    book.has_motion = true;
  }
  flipbooks_.push_back(std::move(book));
  return static_cast<int>(flipbooks_.size()) - 1;
}

void FlipbookRenderer::draw(const std::vector<FlipbookQuad>& quads, int texture, FlipbookBlend blend,
                            const FireFrame& fire, const LightBuffer& lights, const CameraFrame& view,
                            const gpu::RenderTarget& target) {
  if (quads.empty()) return;
  if (texture < 0 || static_cast<size_t>(texture) >= flipbooks_.size())
    throw std::out_of_range("FlipbookRenderer::draw: no such flipbook");
  // Two triangles per quad; v = 0 at the top of the frame (PNG rows run top to bottom).
  vertices_.clear();
  static constexpr int kCorner[6] = {0, 1, 3, 0, 3, 2};
  static constexpr float kU[4] = {0.0f, 1.0f, 0.0f, 1.0f};
  static constexpr float kV[4] = {1.0f, 1.0f, 0.0f, 0.0f};
  for (const FlipbookQuad& q : quads)
    for (int c : kCorner) {
      const glm::vec3& p = q.corners[static_cast<size_t>(c)];
      vertices_.insert(vertices_.end(), {p.x, p.y, p.z, kU[c], kV[c], static_cast<float>(q.frame), q.intensity,
                                         static_cast<float>(q.next_frame), q.blend, q.motion_scale});
    }
  const size_t count = vertices_.size() / kFloatsPerVertex;
  if (count > capacity_) {
    buffer_ = gpu::make_buffer();
    capacity_ = count + count / 2;
    glNamedBufferStorage(buffer_.get(), static_cast<GLsizeiptr>(capacity_ * kFloatsPerVertex * sizeof(float)),
                         nullptr, GL_DYNAMIC_STORAGE_BIT);
  }
  glNamedBufferSubData(buffer_.get(), 0, static_cast<GLsizeiptr>(vertices_.size() * sizeof(float)),
                       vertices_.data());
  glVertexArrayVertexBuffer(vao_.get(), 0, buffer_.get(), 0, kFloatsPerVertex * sizeof(float));

  target.bind();
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_FALSE);
  glDisable(GL_CULL_FACE);
  glEnable(GL_BLEND);
  const Flipbook& book = flipbooks_[static_cast<size_t>(texture)];
  if (book.six_way) {
    // The shader gives the lit smoke premultiplied by its alpha: over, with coverage.
    glBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  } else if (blend == FlipbookBlend::one_minus_destination) {
    // Rose 2007, section 4.3: S = 1 - D, D = 1 on every channel: result = src (1 - dst) + dst.
    glBlendFunc(GL_ONE_MINUS_DST_COLOR, GL_ONE);
  } else {
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  }
  glUseProgram(program_.get());
  glUniformMatrix4fv(gpu::uniform_location(program_, "u_view_projection"), 1, GL_FALSE,
                     glm::value_ptr(view.view_projection));
  glUniform1i(gpu::uniform_location(program_, "u_has_motion"), book.has_motion ? 1 : 0);
  glUniform1i(gpu::uniform_location(program_, "u_six_way"), book.six_way ? 1 : 0);
  glBindTextureUnit(0, book.frames.get());
  if (book.has_motion) glBindTextureUnit(1, book.motion.get());
  if (book.six_way) {
    glBindTextureUnit(2, book.six_way_b.get());
    lights.bind();
    glUniform3fv(gpu::uniform_location(program_, "u_fire_right"), 1, glm::value_ptr(fire.right));
    glUniform3fv(gpu::uniform_location(program_, "u_fire_up"), 1, glm::value_ptr(fire.up));
    glUniform3fv(gpu::uniform_location(program_, "u_fire_toward"), 1, glm::value_ptr(fire.toward));
  }
  glBindVertexArray(vao_.get());
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(count));
  glBindVertexArray(0);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
}

}  // namespace pyro
