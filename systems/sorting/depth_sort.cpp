#include "systems/sorting/depth_sort.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <glm/geometric.hpp>

#include "components/particle_set.h"
#include "components/render_settings.h"
#include "components/view.h"
#include "engine/ecs/world.h"

namespace pyro {

void sort_back_to_front(std::vector<SortKey>& keys) {
  RadixScratch scratch;
  radix_sort_back_to_front(keys, scratch);
}

namespace {

// Particles per task when key making or list filling is split across threads.
constexpr std::size_t kParticlesPerTask = 4096;

// Every set's keys, set after set: set k's particles from offsets[k] on. Each key depends on
// its particle alone, so any split of the work gives the same keys.
void make_keys(const glm::vec3& eye, const glm::vec3& forward, SortKeyKind kind, SortScratch& s) {
  std::vector<std::size_t> offsets(s.sets.size() + 1, 0);
  for (size_t set = 0; set < s.sets.size(); ++set)
    offsets[set + 1] = offsets[set] + s.sets[set].second->size();
  s.keys.resize(offsets.back());
  for (size_t set = 0; set < s.sets.size(); ++set) {
    const ParticlePool& p = *s.sets[set].second;
    SortKey* out = s.keys.data() + offsets[set];
    tbb::parallel_for(
        tbb::blocked_range<size_t>(0, p.size(), kParticlesPerTask),
        [&](const tbb::blocked_range<size_t>& r) {
          for (size_t i = r.begin(); i < r.end(); ++i) {
            const float dx = p.px[i] - eye.x, dy = p.py[i] - eye.y, dz = p.pz[i] - eye.z;
            // Squared distance orders like distance and needs no square root.
            const float depth = kind == SortKeyKind::view_depth
                                    ? dx * forward.x + dy * forward.y + dz * forward.z
                                    : dx * dx + dy * dy + dz * dz;
            out[i] = {depth, static_cast<uint32_t>(set), p.id[i], static_cast<uint32_t>(i)};
          }
        });
  }
}

// Entries [begin, end) of the draw list, from the keys in draw order (s.radix.order).
void fill_draw_list(const SortScratch& s, DrawList& list, size_t begin, size_t end) {
  for (size_t k = begin; k < end; ++k) {
    const SortKey& sorted = s.keys[s.radix.order[k]];
    const ParticlePool& p = *s.sets[sorted.set].second;
    const uint32_t i = sorted.particle;
    list.center_radius[k] = {p.px[i], p.py[i], p.pz[i], p.radius[i]};
    list.color_density[k] = {p.r[i], p.g[i], p.b[i], p.density[i]};
    // The detail key: the golden-ratio fraction of the particle id (mixed with its set's entity
    // index), so consecutive ids spread evenly over [0, 1) and stay put for a particle's life.
    const uint32_t ident = p.id[i] + (s.sets[sorted.set].first << 20);
    const float key = static_cast<float>((ident * 2654435769u) >> 8) * 0x1p-24f;
    list.medium[k] = {p.temperature[i], p.opacity[i], static_cast<float>(p.medium[i]), key};
  }
}

}  // namespace

void build_draw_list(const ecs::World& world, const glm::vec3& eye, const glm::vec3& forward,
                     SortKeyKind kind, SortScratch& s, DrawList& list) {
  s.sets.clear();
  world.each<ParticleSet>(
      [&](ecs::Entity e, const ParticleSet& set) { s.sets.emplace_back(e.index, &set.pool); });
  // Sets in entity-index order, so the tie-break does not depend on the storage's history.
  std::sort(s.sets.begin(), s.sets.end());
  make_keys(eye, forward, kind, s);
  radix_order_back_to_front(s.keys, s.radix);
  list.center_radius.resize(s.keys.size());
  list.color_density.resize(s.keys.size());
  list.medium.resize(s.keys.size());
  tbb::parallel_for(
      tbb::blocked_range<size_t>(0, s.keys.size(), kParticlesPerTask),
      [&](const tbb::blocked_range<size_t>& r) { fill_draw_list(s, list, r.begin(), r.end()); });
}

ecs::SystemDesc sorting_system() {
  return {.name = "sorting",
          .phase = ecs::Phase::sort,
          .access = ecs::Access::of<ecs::Reads<View, RenderSettings, ParticleSet>,
                                    ecs::Writes<EyeDrawLists, SortScratch>>(),
          .run =
              [](ecs::World& world) {
                const View& view = world.resource<const View>();
                if (view.eyes.empty()) return;
                const RenderSettings* settings = world.try_resource<const RenderSettings>();
                const BillboardAlignment alignment =
                    settings ? settings->alignment : RenderSettings{}.alignment;
                SortScratch& scratch = world.resource<SortScratch>();
                EyeDrawLists& lists = world.resource<EyeDrawLists>();
                const std::vector<CameraFrame>& eyes = view.eyes;
                lists.eyes.resize(eyes.size());
                if (alignment == BillboardAlignment::viewplane) {
                  // Parallel view axes: one view-depth order serves every eye.
                  build_draw_list(world, eyes[0].eye, eyes[0].forward, SortKeyKind::view_depth,
                                  scratch, lists.eyes[0]);
                  for (size_t v = 1; v < eyes.size(); ++v) lists.eyes[v] = lists.eyes[0];
                } else {
                  for (size_t v = 0; v < eyes.size(); ++v)
                    build_draw_list(world, eyes[v].eye, eyes[v].forward, SortKeyKind::eye_distance,
                                    scratch, lists.eyes[v]);
                }
              },
          .setup =
              [](ecs::World& world) {
                if (!world.has_resource<SortScratch>()) world.set_resource<SortScratch>();
                if (!world.has_resource<EyeDrawLists>()) world.set_resource<EyeDrawLists>();
              }};
}

}  // namespace pyro
