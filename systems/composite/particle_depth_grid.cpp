#include "systems/composite/particle_depth_grid.h"

#include <algorithm>
#include <cmath>
#include <glm/vec4.hpp>

#include "engine/math/projected_sphere.h"

namespace pyro {

glm::ivec2 particle_depth_cells(glm::ivec2 view) {
  return (glm::max(view, glm::ivec2(1)) + ParticleDepthGrid::cell_pixels - 1) /
         ParticleDepthGrid::cell_pixels;
}

ParticleDepthGrid particle_depth_grid(const DrawList& list, const CameraFrame& camera,
                                      glm::ivec2 view, float reach) {
  ParticleDepthGrid g;
  g.cells = particle_depth_cells(view);
  g.ranges.assign(static_cast<size_t>(g.cells.x) * g.cells.y, ParticleDepthRange{});
  constexpr float margin = 1e-4f;
  const float cell = static_cast<float>(ParticleDepthGrid::cell_pixels);
  for (size_t k = 0; k < list.size(); ++k) {
    const glm::vec4& cr = list.center_radius[k];
    // View depth as the vertex shader has it: -z of the view-space centre.
    const glm::vec3 centre = glm::vec3(camera.view * glm::vec4(glm::vec3(cr), 1.0f));
    const float d = -centre.z;
    const float lo = (d - cr.w) - margin * std::abs(d - cr.w);
    const float hi = (d + cr.w) + margin * std::abs(d + cr.w);
    if (d + cr.w <= 0.0f) continue;  // wholly behind the eye
    glm::ivec2 first(0), last = g.cells - 1;
    ScreenRect rect;
    if (projected_sphere_rect(centre, cr.w, camera.projection, glm::vec2(view), rect)) {
      // Clamped as floats first: a rectangle far outside the view stays representable.
      const glm::vec2 top = glm::vec2(g.cells);
      first = glm::ivec2(glm::clamp(glm::floor((rect.lo - reach) / cell), glm::vec2(0.0f), top));
      last = glm::ivec2(
          glm::clamp(glm::floor((rect.hi + reach) / cell), glm::vec2(-1.0f), top - 1.0f));
    }
    for (int y = first.y; y <= last.y; ++y)
      for (int x = first.x; x <= last.x; ++x)
        g.ranges[static_cast<size_t>(y) * g.cells.x + x].add(lo, hi);
  }
  return g;
}

}  // namespace pyro
