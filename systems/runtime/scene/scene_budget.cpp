#include "systems/runtime/scene/scene_budget.h"

#include <algorithm>
#include <cstdio>

#include "engine/core/user_error.h"
#include "systems/runtime/scene/scene_description.h"

namespace pyro {

uint64_t particle_bytes_estimate(int views, ParticleShape shape) {
  const uint64_t pool = 16 * sizeof(float) + sizeof(uint8_t) + sizeof(uint32_t);
  // systems/sorting/radix_sort.h, kSortBytesPerKey, and the culled list's place per key
  // (depth_sort.h, SortScratch::kept_places).
  const uint64_t sort = 36 + 4;
  constexpr uint64_t kRingSlots = 2, vec4 = 4 * sizeof(float);
  const bool splats = shape == ParticleShape::gaussian;
  const uint64_t once = pool + sort + (splats ? 0 : 3 * vec4);
  // The ring's slots grow by half again: 3/2 of each slot's bytes.
  const uint64_t gpu = kRingSlots * (splats ? 2 * vec4 + sizeof(uint32_t) : 4 * vec4) * 3 / 2;
  const uint64_t per_view = (splats ? sizeof(uint32_t) : 3 * vec4) + gpu;
  return once + per_view * static_cast<uint64_t>(std::max(views, 1));
}

SceneCost estimate_scene_cost(const SceneDescription& scene, int width, int height, int views,
                              int output_width, uint64_t volume_particles) {
  SceneCost cost;
  cost.particles = volume_particles;
  for (const CloudDescription& c : scene.clouds) cost.particles += c.count;
  for (const EmitterDescription& e : scene.emitters) cost.particles += e.emitter.budget;
  const uint64_t pixels = static_cast<uint64_t>(width) * static_cast<uint64_t>(height);
  cost.memory_bytes = cost.particles * particle_bytes_estimate(views, scene.render.particles) +
                      pixels * static_cast<uint64_t>(std::max(views, 1)) * kTargetBytesPerPixelPerView;
  cost.texture_size = std::max({width, height, output_width});
  return cost;
}

namespace {
std::string mib(uint64_t bytes) {
  char text[64];
  std::snprintf(text, sizeof text, "%.1f MiB", static_cast<double>(bytes) / (1024.0 * 1024.0));
  return text;
}
}  // namespace

void check_scene_budget(const SceneDescription& scene, const SceneCost& cost, int driver_max_texture) {
  const SceneBudget& b = scene.budget;
  if (cost.particles > b.particles) {
    throw UserError(scene.file, "/budget/particles",
                    "the scene asks for " + std::to_string(cost.particles) +
                        " particles (clouds' counts + emitters' budgets + volumes), over its budget of " +
                        std::to_string(b.particles) + "; lower the counts or raise budget.particles");
  }
  if (cost.memory_bytes > b.memory_bytes) {
    throw UserError(scene.file, "/budget/memory_mib",
                    "the scene needs an estimated " + mib(cost.memory_bytes) + " (" +
                        std::to_string(cost.particles) + " particles and the render targets), over its budget of " +
                        mib(b.memory_bytes) + "; lower the counts or the size, or raise budget.memory_mib");
  }
  const int limit = b.texture_size > 0 ? std::min(b.texture_size, driver_max_texture) : driver_max_texture;
  if (cost.texture_size > limit) {
    throw UserError(scene.file, "/budget/texture_size",
                    "a render target would be " + std::to_string(cost.texture_size) +
                        " pixels on a side, over the limit of " + std::to_string(limit) +
                        (b.texture_size > 0 ? " (the scene's budget.texture_size)" : " (the driver's largest texture)"));
  }
}

}  // namespace pyro
