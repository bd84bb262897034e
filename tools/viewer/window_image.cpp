#include "tools/viewer/window_image.h"

#include <epoxy/gl.h>

#include <algorithm>

namespace pyro {

SrgbWritesOff::SrgbWritesOff() { glDisable(GL_FRAMEBUFFER_SRGB); }
SrgbWritesOff::~SrgbWritesOff() { glEnable(GL_FRAMEBUFFER_SRGB); }

void present_frame(const gpu::RenderTarget& out, const PanelRect& place, int ww, int wh) {
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, ww, wh);
  glClearColor(0.05f, 0.05f, 0.05f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  const int w = int(place.width), h = int(place.height);
  const int x0 = int(place.x), y0 = wh - int(place.y) - h;  // GL's rows count from the bottom
  glBlitNamedFramebuffer(out.framebuffer(), 0, 0, 0, out.width(), out.height(), x0, y0, x0 + w,
                         y0 + h, GL_COLOR_BUFFER_BIT,
                         w == out.width() && h == out.height() ? GL_NEAREST : GL_LINEAR);
}

std::vector<uint8_t> read_window_rgb(int w, int h) {
  std::vector<uint8_t> rows(size_t(w) * size_t(h) * 3);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, w, h, GL_RGB, GL_UNSIGNED_BYTE, rows.data());
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  std::vector<uint8_t> top_down(rows.size());
  const size_t stride = size_t(w) * 3;
  for (int y = 0; y < h; ++y)
    std::copy_n(rows.begin() + std::ptrdiff_t(size_t(h - 1 - y) * stride), stride,
                top_down.begin() + std::ptrdiff_t(size_t(y) * stride));
  return top_down;
}

}  // namespace pyro
