#pragma once
// Draws pyro view's overlay into the current framebuffer: lines of text in the 5×7 bitmap font
// (viewer_font.h) at an integer scale, on a translucent panel. The vertices are rebuilt only
// when the text changes (set_lines), so an unchanged overlay costs one draw call per frame.
#include <string>
#include <vector>

#include "engine/gpu/gl_objects.h"
#include "systems/viewer/viewer_overlay.h"

namespace pyro {

class TextRenderer {
 public:
  explicit TextRenderer(int scale = 2);  // needs a current OpenGL 4.5 context

  // Pixels per character cell, with the spacing: (5 + 1) · scale by (7 + 3) · scale.
  int cell_width() const { return 6 * scale_; }
  int cell_height() const { return 10 * scale_; }

  void set_lines(const std::vector<OverlayLine>& lines);
  // Draws the lines from the top left corner of a viewport of the given size.
  void draw(int viewport_width, int viewport_height);

 private:
  int scale_;
  gpu::Program program_;
  gpu::Texture atlas_;
  gpu::Buffer vertices_;
  gpu::VertexArray vao_;
  GLint viewport_location_ = -1;
  GLsizei vertex_count_ = 0;
  size_t capacity_ = 0;  // vertices the buffer holds
  std::vector<OverlayLine> lines_;
};

}  // namespace pyro
