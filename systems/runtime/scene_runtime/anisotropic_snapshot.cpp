#include "systems/runtime/scene_runtime/anisotropic_snapshot.h"

#include <algorithm>
#include <chrono>
#include <memory>

#include <epoxy/gl.h>

#include "engine/gpu/render_target.h"
#include "engine/math/camera_math.h"
#include "systems/billboard_render/anisotropic_splat_renderer.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"

namespace pyro {

namespace {

// The renderer of the shared context, made once (after the context, so released before it).
AnisotropicSplatRenderer& shared_renderer() {
  shared_headless_context().make_current();
  static AnisotropicSplatRenderer renderer;
  return renderer;
}

}  // namespace

RgbImage render_anisotropic_snapshot(const std::vector<AnisotropicGaussian>& particles,
                                     const CameraDescription& camera, int width, int height,
                                     const glm::vec3& background, int repeats,
                                     SnapshotTiming* timing) {
  AnisotropicSplatRenderer& renderer = shared_renderer();
  const CameraFrame frame = make_camera_frame(camera.position, camera.target, camera.up, camera.fov_y_deg,
                                              camera.near, camera.far, width, height);
  gpu::RenderTarget target(width, height, GL_RGBA32F);
  std::vector<float> rgba;
  double best = 1e300;
  for (int k = 0; k < std::max(1, repeats); ++k) {
    const auto t0 = std::chrono::steady_clock::now();
    renderer.upload(particles);
    target.bind();
    glClearColor(background.x, background.y, background.z, 1.0f);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    renderer.draw(frame, target);
    rgba = target.read_rgba();
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  if (timing) timing->render_seconds = best;
  RgbImage out;
  out.width = width;
  out.height = height;
  out.rgb.resize(std::size_t(3) * width * height);
  for (std::size_t i = 0; i < std::size_t(width) * height; ++i)
    for (int c = 0; c < 3; ++c) out.rgb[3 * i + c] = rgba[4 * i + c];
  return out;
}

}  // namespace pyro
