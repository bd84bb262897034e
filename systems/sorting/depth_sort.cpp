#include "systems/sorting/depth_sort.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <glm/geometric.hpp>

#include "components/particle_kind.h"
#include "components/particle_set.h"
#include "components/render_settings.h"
#include "components/sort_device_choice.h"
#include "components/view.h"
#include "engine/ecs/world.h"
#include "systems/sorting/gpu_key_layout.h"
#include "systems/sorting/particle_shapes.h"

namespace pyro {

void sort_back_to_front(std::vector<SortKey>& keys) {
  RadixScratch scratch;
  radix_sort_back_to_front(keys, scratch);
}

namespace {

// Particles per task when key making or list filling is split across threads.
constexpr std::size_t kParticlesPerTask = 4096;

// Where each set's particles begin among all the sets' (the last entry: the total).
std::vector<std::size_t> set_offsets(const SortScratch& s) {
  std::vector<std::size_t> offsets(s.sets.size() + 1, 0);
  for (size_t set = 0; set < s.sets.size(); ++set)
    offsets[set + 1] = offsets[set] + s.sets[set].second->size();
  return offsets;
}

// Marks the particles [begin, end) of `p` that can reach a view in `seen`; returns how many.
size_t mark_seen(const ParticlePool& p, std::span<const ViewFrustum> views, size_t begin,
                 size_t end, uint8_t* seen) {
  return mark_spheres_in_any(views, p.px.data() + begin, p.py.data() + begin, p.pz.data() + begin,
                             p.radius.data() + begin, kCullRadii, end - begin, seen + begin);
}

// The keys of particles [begin, end) of set `set` (pool p), at their places in `out`.
void write_keys(const ParticlePool& p, size_t set, const glm::vec3& eye, const glm::vec3& forward,
                SortKeyKind kind, size_t begin, size_t end, SortKey* __restrict out) {
  const float* __restrict x = p.px.data();
  const float* __restrict y = p.py.data();
  const float* __restrict z = p.pz.data();
  const uint32_t* __restrict id = p.id.data();
  for (size_t i = begin; i < end; ++i) {
    const float dx = x[i] - eye.x, dy = y[i] - eye.y, dz = z[i] - eye.z;
    // Squared distance orders like distance and needs no square root.
    const float depth = kind == SortKeyKind::view_depth
                            ? dx * forward.x + dy * forward.y + dz * forward.z
                            : dx * dx + dy * dy + dz * dz;
    out[i] = {depth, static_cast<uint32_t>(set), id[i], static_cast<uint32_t>(i)};
  }
}

// Every set's keys, set after set (set k's particles from offsets[k] on), and which of them can
// reach a view: s.kept_places, in increasing order. Each chunk of kParticlesPerTask particles
// writes its keys and marks and counts what it keeps; then, where some were left out, each chunk
// lists its kept places from its start in the total, so any split of the work gives the same
// result. Returns whether every particle was kept (then s.kept_places is left empty: all are).
bool make_keys(const glm::vec3& eye, const glm::vec3& forward, SortKeyKind kind,
               std::span<const ViewFrustum> views, SortScratch& s) {
  const std::vector<std::size_t> offsets = set_offsets(s);
  s.keys.resize(offsets.back());
  s.seen.resize(offsets.back());
  // Per chunk of every set: its particles among all the sets', and where its kept places begin.
  std::vector<std::pair<size_t, size_t>> chunk_range;
  std::vector<size_t> chunk_start;
  for (size_t set = 0; set < s.sets.size(); ++set) {
    const ParticlePool& p = *s.sets[set].second;
    const size_t first = chunk_range.size();
    for (size_t begin = 0; begin < p.size(); begin += kParticlesPerTask)
      chunk_range.emplace_back(offsets[set] + begin, offsets[set] + std::min(p.size(), begin + kParticlesPerTask));
    chunk_start.resize(chunk_range.size());
    uint8_t* seen = s.seen.data() + offsets[set];
    SortKey* out = s.keys.data() + offsets[set];
    tbb::parallel_for(first, chunk_range.size(), [&](size_t c) {
      const size_t begin = chunk_range[c].first - offsets[set], end = chunk_range[c].second - offsets[set];
      write_keys(p, set, eye, forward, kind, begin, end, out);  // a culled key is just not listed
      chunk_start[c] = mark_seen(p, views, begin, end, seen);
    });
  }
  size_t kept = 0;
  for (size_t& c : chunk_start) kept += std::exchange(c, kept);
  const bool all_kept = kept == offsets.back();
  s.kept_places.resize(all_kept ? 0 : kept);
  if (all_kept) return true;
  uint32_t* places = s.kept_places.data();
  tbb::parallel_for(size_t(0), chunk_range.size(), [&](size_t c) {
    size_t at = chunk_start[c];
    for (size_t i = chunk_range[c].first; i < chunk_range[c].second; ++i)
      if (s.seen[i]) places[at++] = static_cast<uint32_t>(i);
  });
  return false;
}

// The kept keys' indices in draw order (the particles' places among all the sets'): s.radix.order.
void order_kept(bool all_kept, SortScratch& s) {
  if (all_kept)
    radix_order_back_to_front(s.keys, s.radix);
  else
    radix_order_back_to_front(s.keys, s.kept_places, s.radix);
}

// Each particle's instance data packed in key order (s.packed, `stride` vec4s a particle), so
// that the gather in draw order reads one record per particle instead of eight arrays. Stride 4
// adds the light (none: the others' depth 0).
void pack_particles(size_t stride, const SortScratch& s, std::vector<glm::vec4>& records) {
  const std::vector<std::size_t> offsets = set_offsets(s);
  records.resize(offsets.back() * stride);
  for (size_t set = 0; set < s.sets.size(); ++set) {
    const ParticlePool& p = *s.sets[set].second;
    const uint32_t entity = s.sets[set].first;
    const ParticleLight* light = set < s.lights.size() ? s.lights[set] : nullptr;
    const bool lit = light && light->others_depth.size() == p.size();
    glm::vec4* packed = records.data() + offsets[set] * stride;
    tbb::parallel_for(
        tbb::blocked_range<size_t>(0, p.size(), kParticlesPerTask),
        [&](const tbb::blocked_range<size_t>& r) {
          for (size_t i = r.begin(); i < r.end(); ++i) {
            glm::vec4* record = packed + i * stride;
            record[0] = {p.px[i], p.py[i], p.pz[i], p.radius[i]};
            record[1] = {p.r[i], p.g[i], p.b[i], p.density[i]};
            if (stride < 3) continue;
            // The detail key: the golden-ratio fraction of the particle id (mixed with its set's
            // entity index), so consecutive ids spread evenly over [0, 1) and stay put for a
            // particle's life.
            const uint32_t ident = p.id[i] + (entity << 20);
            const float key = static_cast<float>((ident * 2654435769u) >> 8) * 0x1p-24f;
            record[2] = {p.temperature[i], p.opacity[i], static_cast<float>(p.medium[i]), key};
            if (stride > 3) record[3] = lit ? light->others_depth[i] : glm::vec4(0.0f);
          }
        });
  }
}

// Entries [begin, end) of the draw list, from the packed records in draw order (s.radix.order
// indexes the keys, which are laid out like the records). The records are read in a random
// order: each is asked for a few entries ahead, so that the reads overlap.
void fill_draw_list(const SortScratch& s, size_t stride, DrawList& list, size_t begin, size_t end) {
  constexpr size_t kAhead = 16;
  const uint32_t* order = s.radix.order.data();
  const glm::vec4* packed = s.packed.data();
  for (size_t k = begin; k < end; ++k) {
    if (k + kAhead < end) __builtin_prefetch(packed + size_t(order[k + kAhead]) * stride);
    const glm::vec4* record = packed + size_t(order[k]) * stride;
    list.center_radius[k] = record[0];
    list.color_density[k] = record[1];
    if (stride > 2) list.medium[k] = record[2];
    if (stride > 3) list.light[k] = record[3];
  }
}

double ms_since(std::chrono::steady_clock::time_point& start) {
  const auto now = std::chrono::steady_clock::now();
  const double ms = std::chrono::duration<double, std::milli>(now - start).count();
  start = now;
  return ms;
}

}  // namespace

void collect_particle_sets(const ecs::World& world, SortScratch& s) {
  s.sets.clear();
  world.each<ParticleSet>(
      [&](ecs::Entity e, const ParticleSet& set) { s.sets.emplace_back(e.index, &set.pool); });
  // Sets in entity-index order, so the tie-break does not depend on the storage's history.
  std::sort(s.sets.begin(), s.sets.end());
  // Beside each set, the light phase's light for it (lit media), or null.
  const ecs::ComponentPool<ParticleLight>* lights = world.pool<const ParticleLight>();
  s.lights.clear();
  for (const auto& [index, pool] : s.sets)
    s.lights.push_back(lights ? lights->try_get(index) : nullptr);
}

void build_draw_list(const ecs::World& world, const glm::vec3& eye, const glm::vec3& forward,
                     SortKeyKind kind, SortScratch& s, DrawList& list, bool with_medium,
                     std::span<const ViewFrustum> views) {
  collect_particle_sets(world, s);
  auto start = std::chrono::steady_clock::now();
  const bool all_kept = make_keys(eye, forward, kind, views, s);
  s.times.keys_ms += ms_since(start);
  const bool lit = with_medium && std::any_of(s.lights.begin(), s.lights.end(),
                                              [](const ParticleLight* l) { return l != nullptr; });
  const size_t stride = lit ? 4 : with_medium ? 3 : 2;
  pack_particles(stride, s, s.packed);
  s.times.pack_ms += ms_since(start);
  order_kept(all_kept, s);
  s.times.order_ms += ms_since(start);
  const size_t n = s.radix.order.size();
  list.order.clear();
  list.shapes.clear();
  list.center_radius.resize(n);
  list.color_density.resize(n);
  list.medium.resize(with_medium ? n : 0);
  list.light.resize(lit ? n : 0);
  tbb::parallel_for(
      tbb::blocked_range<size_t>(0, n, kParticlesPerTask),
      [&](const tbb::blocked_range<size_t>& r) { fill_draw_list(s, stride, list, r.begin(), r.end()); });
  s.times.gather_ms += ms_since(start);
}

void order_draw_list(const glm::vec3& eye, const glm::vec3& forward, SortKeyKind kind,
                     SortScratch& s, DrawList& list, std::span<const ViewFrustum> views) {
  auto start = std::chrono::steady_clock::now();
  const bool all_kept = make_keys(eye, forward, kind, views, s);
  s.times.keys_ms += ms_since(start);
  order_kept(all_kept, s);
  list.center_radius.clear();
  list.color_density.clear();
  list.medium.clear();
  list.light.clear();
  list.shapes.clear();
  list.order.swap(s.radix.order);  // the old order's storage goes back to the scratch
  s.times.order_ms += ms_since(start);
}

namespace {

// Where this frame's Gaussian lists are ordered: the GPU when asked for or when it measured the
// faster (SortDevice::automatic), unless the key does not fit its layout; else the CPU.
// SortDevice::automatic is returned when the CPU orders but the GPU could (to be measured).
SortDevice gpu_or_cpu(SortDevice asked, const SortDeviceChoice* choice, GpuKeyLayout layout) {
  if (asked == SortDevice::cpu || !layout.fits()) return SortDevice::cpu;
  if (asked == SortDevice::gpu || (choice && choice->measured && choice->gpu)) return SortDevice::gpu;
  return SortDevice::automatic;
}

// How the GPU orders `list`, written over the last frame's request (no allocation in steady state).
void set_gpu_request(const CameraFrame& eye, bool by_eye_distance, std::span<const ViewFrustum> views,
                     DrawList& list) {
  if (!list.gpu_request) list.gpu_request.emplace();
  GpuOrderRequest& r = *list.gpu_request;
  r.eye = eye.eye;
  r.forward = eye.forward;
  r.by_eye_distance = by_eye_distance;
  r.views.assign(views.begin(), views.end());
}

// A mixed scene's list: each entry's kind, its set's. A key's set is its set's place in
// scratch.sets (in entity-index order, as here); the last build_draw_list's order is still in
// scratch.radix.order.
void list_entry_shapes(const ecs::World& world, ParticleShape scene_wide, const SortScratch& s,
                       DrawList& list) {
  std::vector<std::pair<uint32_t, ParticleShape>> set_shapes;
  world.each<const ParticleSet>([&](ecs::Entity e, const ParticleSet&) {
    set_shapes.emplace_back(e.index, particle_shape_of(world, e, scene_wide));
  });
  std::sort(set_shapes.begin(), set_shapes.end());
  list.shapes.resize(s.radix.order.size());
  for (size_t k = 0; k < list.shapes.size(); ++k)
    list.shapes[k] = set_shapes[s.keys[s.radix.order[k]].set].second;
}

// The sorting system's work for one frame: every view's list, indexed for the Gaussian splats
// (their vertex shader reads the pools) and gathered for the billboards that read arrays.
void sort_views(const ecs::World& world, const View& view, const RenderSettings* settings,
                SortScratch& scratch, EyeDrawLists& lists) {
  const RenderSettings defaults;
  const RenderSettings& rs = settings ? *settings : defaults;
  const std::vector<CameraFrame>& eyes = view.eyes;
  lists.eyes.resize(eyes.size());
  // Parallel view axes: one view-depth order serves every eye.
  const bool shared = rs.alignment == BillboardAlignment::viewplane;
  const SortKeyKind kind = shared ? SortKeyKind::view_depth : SortKeyKind::eye_distance;
  const size_t orders = shared ? 1 : eyes.size();
  std::vector<ViewFrustum> frusta;
  for (const CameraFrame& e : eyes) frusta.push_back(view_frustum(e));
  // The views order v's list is drawn into: every eye when they share it, else eye v (none:
  // nothing is culled).
  auto views_of = [&](size_t v) {
    if (!rs.cull_particles) return std::span<const ViewFrustum>();
    return shared ? std::span<const ViewFrustum>(frusta) : std::span<const ViewFrustum>(&frusta[v], 1);
  };
  // Sets of one kind: that kind's list; of different kinds (a mixed scene), one gathered list
  // in one back-to-front order with each entry's kind.
  const std::optional<ParticleShape> common = common_particle_shape(world, rs.particles);
  if (common == ParticleShape::gaussian) {
    collect_particle_sets(world, scratch);
    lists.pools.clear();
    for (const auto& set : scratch.sets) lists.pools.push_back(set.second);
    lists.lights = scratch.lights;
    const SortDevice device = gpu_or_cpu(rs.sort_device, world.try_resource<const SortDeviceChoice>(),
                                         gpu_key_layout(lists.pools));
    for (size_t v = 0; v < orders; ++v) {
      DrawList& list = lists.eyes[v];
      list.on_gpu = device == SortDevice::gpu;
      if (list.on_gpu) list.order.clear();
      else order_draw_list(eyes[v].eye, eyes[v].forward, kind, scratch, list, views_of(v));
      // Kept on a CPU list too, while undecided: billboard_render measures the GPU's order of it.
      if (device == SortDevice::cpu) list.gpu_request.reset();
      else set_gpu_request(eyes[v], !shared, views_of(v), list);
    }
  } else {
    lists.pools.clear();
    lists.lights.clear();
    for (size_t v = 0; v < orders; ++v) {
      build_draw_list(world, eyes[v].eye, eyes[v].forward, kind, scratch, lists.eyes[v],
                      rs.media_layers(), views_of(v));
      lists.eyes[v].gpu_request.reset();
      lists.eyes[v].on_gpu = false;
      if (!common) list_entry_shapes(world, rs.particles, scratch, lists.eyes[v]);
    }
  }
  for (size_t v = orders; v < eyes.size(); ++v) lists.eyes[v] = lists.eyes[0];
}

}  // namespace

ecs::SystemDesc sorting_system() {
  return {.name = "sorting",
          .phase = ecs::Phase::sort,
          .access = ecs::Access::of<ecs::Reads<View, RenderSettings, ParticleSet, ParticleKind, ParticleLight, SortDeviceChoice>,
                                    ecs::Writes<EyeDrawLists, SortScratch>>(),
          .run =
              [](ecs::World& world) {
                const View& view = world.resource<const View>();
                if (view.eyes.empty()) return;
                SortScratch& scratch = world.resource<SortScratch>();
                scratch.times = {};
                sort_views(world, view, world.try_resource<const RenderSettings>(), scratch,
                           world.resource<EyeDrawLists>());
              },
          .setup =
              [](ecs::World& world) {
                if (!world.has_resource<SortScratch>()) world.set_resource<SortScratch>();
                if (!world.has_resource<EyeDrawLists>()) world.set_resource<EyeDrawLists>();
              }};
}

}  // namespace pyro
