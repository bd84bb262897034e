#include "systems/output/transparent_frame.h"

#include <algorithm>
#include <cmath>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "components/gpu_frame.h"
#include "components/render_settings.h"
#include "engine/gpu/render_target.h"
#include "engine/math/anaglyph.h"
#include "engine/math/color.h"
#include "engine/math/highlight_rolloff.h"

namespace pyro {

namespace {

// The background as a target of `format` holds it: a 1x1 target cleared as the mesh renderer
// clears the scene target (GL's conversion of the clear colour, sRGB encoding on), read back
// linear.
glm::vec3 cleared_color(GLenum format, const glm::vec3& background) {
  GLint bound = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &bound);
  const GLboolean encoding = glIsEnabled(GL_FRAMEBUFFER_SRGB);
  const gpu::RenderTarget probe(1, 1, format);
  probe.bind();
  glEnable(GL_FRAMEBUFFER_SRGB);
  glClearColor(background.x, background.y, background.z, 0.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  // Decoded as the passes that read the scene decode it (GL's sRGB decode, not the CPU's
  // formula: on llvmpipe they differ by up to 1e-3 of the value): blitted into a float target.
  const gpu::RenderTarget decoded(1, 1, GL_RGBA32F);
  glBlitNamedFramebuffer(probe.framebuffer(), decoded.framebuffer(), 0, 0, 1, 1, 0, 0, 1, 1,
                         GL_COLOR_BUFFER_BIT, GL_NEAREST);
  const std::vector<float> values = decoded.read_rgba();
  const glm::vec3 held(values[0], values[1], values[2]);
  if (!encoding) glDisable(GL_FRAMEBUFFER_SRGB);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(bound));
  return held;
}

// What the final pass makes of one colour seen by every view (compositor.cpp): L + R for an
// anaglyph, each view alone otherwise.
glm::mat3 shown_views_matrix(StereoMode mode) {
  switch (mode) {
    case StereoMode::anaglyph:
    case StereoMode::anaglyph_color:
    case StereoMode::anaglyph_half_color: {
      const AnaglyphMatrices m = anaglyph_matrices(mode == StereoMode::anaglyph ? AnaglyphKind::dubois
                                                   : mode == StereoMode::anaglyph_color
                                                       ? AnaglyphKind::color
                                                       : AnaglyphKind::half_color);
      return m.left + m.right;
    }
    default:
      return glm::mat3(1.0f);
  }
}

// The least alpha (0..255) at which the straight colour (O - B (1 - a)) / a of every channel
// lies in [0, 255]: above B the colour's room is 255 - B, below it B. 0 only where O is B.
int least_alpha(const uint8_t* opaque, const std::array<float, 3>& background255) {
  double need = 0.0;
  for (int k = 0; k < 3; ++k) {
    const double d = opaque[k] - background255[size_t(k)];
    const double room = d > 0.0 ? 255.0 - background255[size_t(k)] : background255[size_t(k)];
    if (std::abs(d) > 0.5) need = std::max(need, room > 0.0 ? std::abs(d) / room : 1.0);
  }
  return std::clamp(static_cast<int>(std::ceil(need * 255.0 - 1e-6)), 0, 255);
}

}  // namespace

std::optional<FrameBackground> held_background(ecs::World& world) {
  const RenderSettings* settings = world.try_resource<const RenderSettings>();
  const GpuFrame* frame = world.try_resource<const GpuFrame>();
  if (!settings || !settings->transparent || !frame || frame->eyes.empty()) return std::nullopt;
  const EyeTargets& eye = frame->eyes[0];
  const glm::vec3 held = cleared_color(eye.scene->format(), settings->background);
  // A layered view is read through the composite's arithmetic, highlights rolled off
  // (linear_readback.h); an unlayered one is its scene target.
  const bool layered = eye.layer || eye.media_atlas;
  const glm::vec3 linear = layered ? roll_off_highlights(held) : held;
  const glm::vec3 shown = roll_off_highlights(shown_views_matrix(settings->stereo_mode) * held);
  FrameBackground b;
  for (int k = 0; k < 3; ++k) {
    b.linear[size_t(k)] = linear[k];
    b.shown[size_t(k)] = linear_to_srgb_polynomial(shown[k]);
  }
  return b;
}

void remove_linear_background(std::vector<float>& rgba, const std::array<float, 3>& background) {
  for (size_t i = 0; i + 3 < rgba.size(); i += 4) {
    const float uncovered = 1.0f - rgba[i + 3];
    for (size_t k = 0; k < 3; ++k) rgba[i + k] -= background[k] * uncovered;
  }
}

ShownImage straight_alpha_image(const ShownImage& shown, const std::array<float, 3>& background) {
  std::array<float, 3> b255;
  for (size_t k = 0; k < 3; ++k) b255[k] = std::clamp(background[k], 0.0f, 1.0f) * 255.0f;
  ShownImage out{shown.width, shown.height, std::vector<uint8_t>(shown.rgba.size(), 0)};
  for (size_t i = 0; i + 3 < shown.rgba.size(); i += 4) {
    const uint8_t* o = &shown.rgba[i];
    const int a = std::max<int>(o[3], least_alpha(o, b255));
    out.rgba[i + 3] = static_cast<uint8_t>(a);
    if (a == 0) continue;  // nothing here: the colour is the background's, all of it
    const double alpha = a / 255.0;
    for (size_t k = 0; k < 3; ++k) {
      const double c = (o[k] - b255[k] * (1.0 - alpha)) / alpha;
      out.rgba[i + k] = static_cast<uint8_t>(std::clamp(std::lround(c), 0l, 255l));
    }
  }
  return out;
}

}  // namespace pyro
