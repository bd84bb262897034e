#include "systems/sorting/depth_sort.h"

#include <algorithm>

#include <glm/geometric.hpp>

#include "components/camera.h"
#include "components/particle_set.h"
#include "engine/ecs/world.h"

namespace pyro {

void sort_back_to_front(std::vector<SortKey>& keys) {
  std::sort(keys.begin(), keys.end(), back_to_front);
}

namespace {

// Per-frame scratch kept between frames so sorting allocates nothing in steady state.
struct SortScratch {
  std::vector<SortKey> keys;
  std::vector<std::pair<uint32_t, const ParticlePool*>> sets;  // (entity index, pool)
};

}  // namespace

void build_draw_list(ecs::World& world, const glm::vec3& eye, const glm::vec3& forward,
                     DrawList& list) {
  if (!world.has_resource<SortScratch>()) world.set_resource<SortScratch>();
  SortScratch& s = world.resource<SortScratch>();
  s.sets.clear();
  world.each<ParticleSet>([&](ecs::Entity e, ParticleSet& set) { s.sets.emplace_back(e.index, &set.pool); });
  // Sets in entity-index order, so the tie-break does not depend on the storage's history.
  std::sort(s.sets.begin(), s.sets.end());
  s.keys.clear();
  for (size_t set = 0; set < s.sets.size(); ++set) {
    const ParticlePool& p = *s.sets[set].second;
    for (size_t i = 0; i < p.size(); ++i) {
      const float depth = (p.px[i] - eye.x) * forward.x + (p.py[i] - eye.y) * forward.y +
                          (p.pz[i] - eye.z) * forward.z;
      s.keys.push_back({depth, static_cast<uint32_t>(set), p.id[i], static_cast<uint32_t>(i)});
    }
  }
  sort_back_to_front(s.keys);
  list.center_radius.resize(s.keys.size());
  list.color_density.resize(s.keys.size());
  for (size_t k = 0; k < s.keys.size(); ++k) {
    const ParticlePool& p = *s.sets[s.keys[k].set].second;
    const uint32_t i = s.keys[k].particle;
    list.center_radius[k] = {p.px[i], p.py[i], p.pz[i], p.radius[i]};
    list.color_density[k] = {p.r[i], p.g[i], p.b[i], p.density[i]};
  }
}

ecs::SystemDesc depth_sort_system() {
  return {"sorting", ecs::Phase::sort, ecs::access<Camera, ParticleSet>(),
          ecs::access<DrawList>(), [](ecs::World& world) {
            glm::vec3 eye{0.0f}, forward{0.0f, 0.0f, -1.0f};
            bool found = false;
            world.each<Camera>([&](Camera& c) {
              if (found) return;  // the first camera decides the order
              eye = c.position;
              forward = glm::normalize(c.target - c.position);
              found = true;
            });
            DrawList& list = world.has_resource<DrawList>() ? world.resource<DrawList>()
                                                            : world.set_resource<DrawList>();
            build_draw_list(world, eye, forward, list);
          }};
}

}  // namespace pyro
