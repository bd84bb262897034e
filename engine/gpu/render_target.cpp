#include "engine/gpu/render_target.h"

#include <atomic>
#include <string>

#include "engine/gpu/gpu_error.h"

namespace pyro::gpu {

namespace {
std::atomic<uint64_t> next_serial{1};
}  // namespace

RenderTarget::RenderTarget(int width, int height, GLenum color_format)
    : width_(width), height_(height), format_(color_format), serial_(next_serial++) {
  if (width < 1 || height < 1) throw GpuError("render target needs a positive size");
  GLint max_size = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
  if (width > max_size || height > max_size) {
    throw GpuError("render target " + std::to_string(width) + "x" + std::to_string(height) +
                   " exceeds the driver's largest texture, " + std::to_string(max_size));
  }
  color_ = make_texture(GL_TEXTURE_2D);
  glTextureStorage2D(color_.get(), 1, color_format, width, height);
  glTextureParameteri(color_.get(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(color_.get(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  // Upsampling a layer reads past its last texel at the border: clamp, never wrap around.
  glTextureParameteri(color_.get(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(color_.get(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  depth_ = make_texture(GL_TEXTURE_2D);
  glTextureStorage2D(depth_.get(), 1, GL_DEPTH_COMPONENT32F, width, height);
  fbo_ = make_framebuffer();
  glNamedFramebufferTexture(fbo_.get(), GL_COLOR_ATTACHMENT0, color_.get(), 0);
  glNamedFramebufferTexture(fbo_.get(), GL_DEPTH_ATTACHMENT, depth_.get(), 0);
  const GLenum status = glCheckNamedFramebufferStatus(fbo_.get(), GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw GpuError("offscreen framebuffer incomplete (status " + std::to_string(status) + ")");
}

void RenderTarget::bind() const {
  ++binds_;
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.get());
  glViewport(0, 0, width_, height_);
}

namespace {
template <class T>
void flip_rows(std::vector<T>& data, int width, int height, int channels) {
  const size_t row = static_cast<size_t>(width) * channels;
  for (int y = 0; y < height / 2; ++y) {
    T* a = data.data() + static_cast<size_t>(y) * row;
    T* b = data.data() + static_cast<size_t>(height - 1 - y) * row;
    for (size_t k = 0; k < row; ++k) std::swap(a[k], b[k]);
  }
}
}  // namespace

std::vector<float> RenderTarget::read_rgba() const {
  std::vector<float> pixels(static_cast<size_t>(width_) * height_ * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTextureImage(color_.get(), 0, GL_RGBA, GL_FLOAT,
                    static_cast<GLsizei>(pixels.size() * sizeof(float)), pixels.data());
  flip_rows(pixels, width_, height_, 4);
  return pixels;
}

std::vector<uint8_t> RenderTarget::read_rgba8() const {
  std::vector<uint8_t> pixels(static_cast<size_t>(width_) * height_ * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTextureImage(color_.get(), 0, GL_RGBA, GL_UNSIGNED_BYTE,
                    static_cast<GLsizei>(pixels.size()), pixels.data());
  flip_rows(pixels, width_, height_, 4);
  return pixels;
}

std::vector<float> RenderTarget::read_depth() const {
  std::vector<float> depth(static_cast<size_t>(width_) * height_);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTextureImage(depth_.get(), 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                    static_cast<GLsizei>(depth.size() * sizeof(float)), depth.data());
  flip_rows(depth, width_, height_, 1);
  return depth;
}

}  // namespace pyro::gpu
