#include "systems/composite/opaque_view_readback.h"

#include <stdexcept>
#include <string>

#include "engine/math/camera_math.h"
#include "engine/math/color.h"
#include "systems/composite/particle_depth_grid.h"

namespace pyro {

OpaqueView read_opaque_view(const GpuFrame& frame, const View& view, const EyeDrawLists& lists,
                            size_t eye) {
  if (eye >= frame.eyes.size() || eye >= view.eyes.size() || eye >= lists.eyes.size())
    throw std::logic_error("read_opaque_view: no view " + std::to_string(eye));
  const EyeTargets& t = frame.eyes[eye];
  if (!t.media_atlas && !t.layer)
    throw std::logic_error(
        "read_opaque_view: the particles are drawn into the scene target (no layer)");
  const gpu::RenderTarget& scene = *t.scene;
  OpaqueView v;
  v.width = scene.width();
  v.height = scene.height();
  if (scene.format() == GL_SRGB8_ALPHA8) {
    const std::vector<uint8_t> bytes = scene.read_rgba8();
    v.rgba.resize(bytes.size());
    for (size_t i = 0; i < bytes.size(); ++i)
      v.rgba[i] = i % 4 == 3 ? bytes[i] / 255.0f : srgb_to_linear(bytes[i] / 255.0f);
  } else {
    v.rgba = scene.read_rgba();
  }
  v.view_depth = scene.read_depth();
  const CameraFrame& camera = view.eyes[eye];
  for (float& d : v.view_depth) d = window_to_view_depth(d, camera.near, camera.far);
  const ParticleDepthGrid grid =
      particle_depth_grid(lists.eyes[eye], camera, {v.width, v.height}, 0.0f);
  v.particle_far.assign(v.view_depth.size(), 0.0f);
  for (int y = 0; y < v.height; ++y)
    for (int x = 0; x < v.width; ++x) {
      // Rows top first; the grid's from the bottom.
      const glm::ivec2 cell = glm::ivec2(x, v.height - 1 - y) / ParticleDepthGrid::cell_pixels;
      const ParticleDepthRange& r =
          grid.ranges[static_cast<size_t>(cell.y) * grid.cells.x + cell.x];
      if (!r.empty()) v.particle_far[static_cast<size_t>(y) * v.width + x] = r.far;
    }
  return v;
}

}  // namespace pyro
