#include "systems/lighting/flipbook_fire_lights.h"

#include <algorithm>

#include <glm/geometric.hpp>

#include "engine/math/flipbook_sequence.h"

namespace pyro {

std::vector<PointEmitter> flipbook_fire_emitters(const FlipbookFire& fire, const FlipbookEmission& emission,
                                                 double seconds) {
  std::vector<PointEmitter> out;
  const int frames = int(emission.frame_radiance.size());
  if (frames == 0 || fire.frame_count != frames) return out;
  const double width = fire.width, height = double(fire.width) * fire.aspect;
  const glm::dvec3 up = glm::normalize(glm::dvec3(fire.up));
  const glm::dvec3 middle = glm::dvec3(fire.position) + 0.5 * height * up;
  const int64_t step = flipbook_step(seconds, fire.frames_per_second);
  const double flicker = flame_flicker(flicker_of(fire), seconds);
  for (const FlipbookBillboard& b : fire.billboards) {
    const int f = flipbook_frame(b.start_frame, b.increment, step, frames);
    const glm::dvec3 radiance = glm::dvec3(emission.frame_radiance[size_t(f)]) * (double(b.intensity) * flicker);
    out.push_back({middle, radiance * (width * height), 0.5 * std::min(width, height)});
  }
  return out;
}

}  // namespace pyro
