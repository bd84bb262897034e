#pragma once
// An offscreen framebuffer: a floating-point colour attachment (RGBA16F by default, linear
// radiance, premultiplied alpha) and a 32-bit float depth attachment.
#include <cstdint>
#include <vector>

#include "engine/gpu/gl_objects.h"

namespace pyro::gpu {

class RenderTarget {
 public:
  RenderTarget(int width, int height, GLenum color_format = GL_RGBA16F);

  int width() const { return width_; }
  int height() const { return height_; }
  GLuint framebuffer() const { return fbo_.get(); }
  GLuint color_texture() const { return color_.get(); }
  GLenum format() const { return format_; }  // the colour texture's internal format
  GLuint depth_texture() const { return depth_.get(); }

  // Binds the framebuffer for drawing, with the viewport on the whole target. Passes draw into
  // a target through bind(), so binds() counts the times it may have been drawn into: a pass that
  // sees the count unchanged since its own draw knows the target still holds what it drew.
  void bind() const;
  uint64_t binds() const { return binds_; }
  // Unique over the process (GL object names are reused once deleted).
  uint64_t serial() const { return serial_; }
  // RGBA floats, row 0 at the top of the image (GL's bottom-up rows are flipped).
  std::vector<float> read_rgba() const;
  // RGBA bytes as stored (sRGB-encoded for an sRGB target), row 0 at the top.
  std::vector<uint8_t> read_rgba8() const;
  // Depth values in [0, 1], row 0 at the top.
  std::vector<float> read_depth() const;

 private:
  int width_, height_;
  GLenum format_;
  Texture color_, depth_;
  Framebuffer fbo_;
  uint64_t serial_;
  mutable uint64_t binds_ = 0;
};

}  // namespace pyro::gpu
