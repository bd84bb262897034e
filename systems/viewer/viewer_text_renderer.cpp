#include "systems/viewer/viewer_text_renderer.h"

#include <algorithm>
#include <array>

#include "engine/gpu/shader_program.h"
#include "systems/viewer/viewer_font.h"

namespace pyro {

namespace {

struct Vertex {
  float x, y;  // window pixels
  float u, v;  // atlas texels
  float r, g, b, a;
};

// Atlas: one 5×7 cell per character code 0..127 side by side; cell 0 is solid (the panel).
constexpr int atlas_cells = 128;

}  // namespace

TextRenderer::TextRenderer(int scale)
    : scale_(std::max(scale, 1)),
      program_(gpu::load_program("overlay_text.vert", "overlay_text.frag")),
      atlas_(gpu::make_texture(GL_TEXTURE_2D)),
      vertices_(gpu::make_buffer()),
      vao_(gpu::make_vertex_array()) {
  std::vector<uint8_t> texels(size_t(atlas_cells * glyph_width * glyph_height), 0);
  for (int c = 0; c < atlas_cells; ++c) {
    const Glyph solid = {0x1f, 0x1f, 0x1f, 0x1f, 0x1f, 0x1f, 0x1f};
    const Glyph& g = c == 0 ? solid : glyph_for(char(c));
    for (int row = 0; row < glyph_height; ++row)
      for (int x = 0; x < glyph_width; ++x)
        if (g[size_t(row)] & (1u << (4 - x)))
          texels[size_t(row * atlas_cells * glyph_width + c * glyph_width + x)] = 255;
  }
  glTextureStorage2D(atlas_.get(), 1, GL_R8, atlas_cells * glyph_width, glyph_height);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTextureSubImage2D(atlas_.get(), 0, 0, 0, atlas_cells * glyph_width, glyph_height, GL_RED,
                      GL_UNSIGNED_BYTE, texels.data());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  viewport_location_ = gpu::uniform_location(program_, "u_viewport");

  const GLuint vao = vao_.get();
  glEnableVertexArrayAttrib(vao, 0);
  glEnableVertexArrayAttrib(vao, 1);
  glEnableVertexArrayAttrib(vao, 2);
  glVertexArrayAttribFormat(vao, 0, 2, GL_FLOAT, GL_FALSE, offsetof(Vertex, x));
  glVertexArrayAttribFormat(vao, 1, 2, GL_FLOAT, GL_FALSE, offsetof(Vertex, u));
  glVertexArrayAttribFormat(vao, 2, 4, GL_FLOAT, GL_FALSE, offsetof(Vertex, r));
  for (GLuint a = 0; a < 3; ++a) glVertexArrayAttribBinding(vao, a, 0);
}

void TextRenderer::set_lines(const std::vector<OverlayLine>& lines) {
  if (lines.size() == lines_.size() &&
      std::equal(lines.begin(), lines.end(), lines_.begin(), [](const OverlayLine& a, const OverlayLine& b) {
        return a.text == b.text && a.error == b.error;
      }))
    return;
  lines_ = lines;
  std::vector<Vertex> v;
  const float s = float(scale_);
  const auto quad = [&](float x0, float y0, float x1, float y1, float u0, float v0, float u1,
                        float v1, const std::array<float, 4>& c) {
    const Vertex corners[4] = {{x0, y0, u0, v0, c[0], c[1], c[2], c[3]},
                               {x1, y0, u1, v0, c[0], c[1], c[2], c[3]},
                               {x1, y1, u1, v1, c[0], c[1], c[2], c[3]},
                               {x0, y1, u0, v1, c[0], c[1], c[2], c[3]}};
    for (int k : {0, 1, 2, 0, 2, 3}) v.push_back(corners[k]);
  };
  size_t longest = 0;
  for (const OverlayLine& l : lines_) longest = std::max(longest, l.text.size());
  if (!lines_.empty()) {
    // The panel: a solid texel (cell 0) stretched behind the text, 4 scaled pixels of margin.
    const float w = float(longest) * float(cell_width()) + 8 * s;
    const float h = float(lines_.size()) * float(cell_height()) + 6 * s;
    quad(0, 0, w, h, 0.5f, 0.5f, 0.5f, 0.5f, {0.0f, 0.0f, 0.0f, 0.55f});
  }
  for (size_t row = 0; row < lines_.size(); ++row) {
    const std::array<float, 4> color = lines_[row].error ? std::array<float, 4>{1.0f, 0.35f, 0.3f, 1.0f}
                                                         : std::array<float, 4>{0.95f, 0.95f, 0.9f, 1.0f};
    const float y = 4 * s + float(row) * float(cell_height());
    for (size_t col = 0; col < lines_[row].text.size(); ++col) {
      const char c = lines_[row].text[col];
      if (c == ' ') continue;
      unsigned code = static_cast<unsigned char>(c);
      if (code >= 'a' && code <= 'z') code -= 'a' - 'A';
      if (code >= unsigned(atlas_cells) || code == 0 || !is_drawable(c)) code = 127;  // the box
      const float x = 4 * s + float(col) * float(cell_width());
      const float u = float(code * glyph_width);
      quad(x, y, x + glyph_width * s, y + glyph_height * s, u, 0, u + glyph_width, glyph_height, color);
    }
  }
  vertex_count_ = GLsizei(v.size());
  if (v.size() > capacity_) {
    capacity_ = std::max(v.size(), capacity_ * 2);
    vertices_ = gpu::make_buffer();
    glNamedBufferData(vertices_.get(), GLsizeiptr(capacity_ * sizeof(Vertex)), nullptr, GL_DYNAMIC_DRAW);
    glVertexArrayVertexBuffer(vao_.get(), 0, vertices_.get(), 0, sizeof(Vertex));
  }
  if (!v.empty())
    glNamedBufferSubData(vertices_.get(), 0, GLsizeiptr(v.size() * sizeof(Vertex)), v.data());
}

void TextRenderer::draw(int viewport_width, int viewport_height) {
  if (vertex_count_ == 0) return;
  glViewport(0, 0, viewport_width, viewport_height);
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
  glUseProgram(program_.get());
  glUniform2f(viewport_location_, float(viewport_width), float(viewport_height));
  glBindTextureUnit(0, atlas_.get());
  glBindVertexArray(vao_.get());
  glDrawArrays(GL_TRIANGLES, 0, vertex_count_);
  glBindVertexArray(0);
  glDisable(GL_BLEND);
}

}  // namespace pyro
