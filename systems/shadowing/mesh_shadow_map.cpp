#include "systems/shadowing/mesh_shadow_map.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>
#include <tbb/parallel_for.h>

#include "components/scene_lighting.h"
#include "components/shadow_settings.h"
#include "engine/ecs/world.h"
#include "engine/math/light_space_texture.h"
#include "engine/math/shadow_ray_index.h"

namespace pyro {

bool casts_shadow(MeshKind kind) { return kind != MeshKind::ground_plane; }

namespace {

// The grid's light-space frame: u, v across the light, w along it; texel (i, j) centred at
// (u0 + (i + 0.5) du, v0 + (j + 0.5) du); depth w0 + z (w1 - w0), z in [0, 1].
struct GridFrame {
  glm::dvec3 u{1, 0, 0}, v{0, 1, 0}, w{0, 0, 1};
  double u0 = 0, v0 = 0, du = 1, w0 = 0, w1 = 1;
  int nu = 0, nv = 0;
};

struct Bounds {
  glm::dvec3 lo{std::numeric_limits<double>::max()};
  glm::dvec3 hi{-std::numeric_limits<double>::max()};
  void add(const glm::dvec3& p) { lo = glm::min(lo, p), hi = glm::max(hi, p); }
  bool empty() const { return lo.x > hi.x; }
};

// Every instance's vertices in light space (u, v, w), casters and all.
Bounds light_space_bounds(const std::vector<MeshInstance>& instances, const GridFrame& f, bool casters_only) {
  Bounds b;
  for (const MeshInstance& m : instances) {
    if (!m.geometry || (casters_only && !casts_shadow(m.kind))) continue;
    for (const glm::vec3& q : m.geometry->data.positions) {
      const glm::dvec3 p(m.placement.apply(q));
      b.add({glm::dot(p, f.u), glm::dot(p, f.v), glm::dot(p, f.w)});
    }
  }
  return b;
}

GridFrame fit_grid(const std::vector<MeshInstance>& instances, const glm::dvec3& light_travel, int across,
                   bool& any) {
  GridFrame f;
  f.w = glm::normalize(light_travel);
  orthonormal_basis(-f.w, f.u, f.v);
  const Bounds casters = light_space_bounds(instances, f, true);
  any = !casters.empty();
  if (!any) return f;
  const Bounds all = light_space_bounds(instances, f, false);
  across = std::max(across, 4);
  const double extent = std::max({casters.hi.x - casters.lo.x, casters.hi.y - casters.lo.y, 1e-6});
  f.du = extent / (across - 2);
  f.nu = int(std::ceil((casters.hi.x - casters.lo.x) / f.du)) + 2;
  f.nv = int(std::ceil((casters.hi.y - casters.lo.y) / f.du)) + 2;
  f.u0 = casters.lo.x - f.du;
  f.v0 = casters.lo.y - f.du;
  const double pad = 1e-3 * std::max(all.hi.z - all.lo.z, 1e-6);
  f.w0 = all.lo.z - pad;
  f.w1 = all.hi.z + pad;
  return f;
}

glm::mat4 grid_world_to_texture(const GridFrame& f) {
  return light_space_texture(f.u, f.v, f.w, {f.u0, f.v0, f.w0}, {f.nu * f.du, f.nv * f.du, f.w1 - f.w0});
}

// A caster triangle in grid coordinates: x, y in texels (centres at + 0.5), z in [0, 1].
using GridTriangle = std::array<glm::dvec3, 3>;

std::vector<GridTriangle> caster_triangles(const std::vector<MeshInstance>& instances, const GridFrame& f) {
  std::vector<GridTriangle> out;
  const auto grid = [&](const glm::dvec3& p) {
    return glm::dvec3((glm::dot(p, f.u) - f.u0) / f.du, (glm::dot(p, f.v) - f.v0) / f.du,
                      (glm::dot(p, f.w) - f.w0) / (f.w1 - f.w0));
  };
  for (const MeshInstance& m : instances) {
    if (!m.geometry || !casts_shadow(m.kind)) continue;
    const MeshData& d = m.geometry->data;
    for (size_t t = 0; t + 2 < d.indices.size(); t += 3) {
      GridTriangle g;
      for (int k = 0; k < 3; ++k) g[size_t(k)] = grid(glm::dvec3(m.placement.apply(d.positions[d.indices[t + size_t(k)]])));
      out.push_back(g);
    }
  }
  return out;
}

// The nearest depth of `t` at the centres of rows [j_begin, j_end) it covers (edge functions;
// a centre on an edge counts for either side), into `depth`.
void rasterise_rows(const GridTriangle& t, int nu, int j_begin, int j_end, std::vector<float>& depth) {
  const glm::dvec3 &a = t[0], &b = t[1], &c = t[2];
  const double area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  if (std::abs(area) < 1e-12) return;  // seen edge-on: it covers no centre
  const int i0 = std::max(0, int(std::ceil(std::min({a.x, b.x, c.x}) - 0.5)));
  const int i1 = std::min(nu - 1, int(std::floor(std::max({a.x, b.x, c.x}) - 0.5)));
  const int j0 = std::max(j_begin, int(std::ceil(std::min({a.y, b.y, c.y}) - 0.5)));
  const int j1 = std::min(j_end - 1, int(std::floor(std::max({a.y, b.y, c.y}) - 0.5)));
  for (int j = j0; j <= j1; ++j)
    for (int i = i0; i <= i1; ++i) {
      const double x = i + 0.5, y = j + 0.5;
      const double wa = ((b.x - x) * (c.y - y) - (b.y - y) * (c.x - x)) / area;
      const double wb = ((c.x - x) * (a.y - y) - (c.y - y) * (a.x - x)) / area;
      const double wc = 1.0 - wa - wb;
      if (wa < 0.0 || wb < 0.0 || wc < 0.0) continue;
      float& d = depth[size_t(j) * size_t(nu) + size_t(i)];
      d = std::min(d, float(wa * a.z + wb * b.z + wc * c.z));
    }
}

}  // namespace

void build_mesh_shadow_map(const std::vector<MeshInstance>& instances, const glm::dvec3& light_travel,
                           int across, MeshShadow& out) {
  const uint64_t version = out.version + 1;
  bool any = false;
  const GridFrame f = fit_grid(instances, light_travel, across, any);
  if (!any) {
    out = MeshShadow{};
    out.version = version;
    return;
  }
  const std::vector<GridTriangle> triangles = caster_triangles(instances, f);
  out.size = {f.nu, f.nv};
  out.depth.assign(size_t(f.nu) * size_t(f.nv), 1.0f);
  constexpr int kRowsPerTask = 16;
  tbb::parallel_for(0, (f.nv + kRowsPerTask - 1) / kRowsPerTask, [&](int band) {
    const int j_begin = band * kRowsPerTask, j_end = std::min(f.nv, j_begin + kRowsPerTask);
    for (const GridTriangle& t : triangles) rasterise_rows(t, f.nu, j_begin, j_end, out.depth);
  });
  out.world_to_texture = grid_world_to_texture(f);
  out.texel_depth = float(f.du / (f.w1 - f.w0));
  out.version = version;
}

double mesh_visibility(const MeshShadow& shadow, const glm::vec3& p, double bias_texels) {
  if (shadow.empty()) return 1.0;
  const glm::vec4 t = shadow.world_to_texture * glm::vec4(p, 1.0f);
  const double x = double(t.x) * shadow.size.x - 0.5, y = double(t.y) * shadow.size.y - 0.5;
  const double z = double(t.z) - bias_texels * shadow.texel_depth;
  const int i = int(std::floor(x)), j = int(std::floor(y));
  const double fx = x - i, fy = y - j;
  const auto lit = [&](int a, int b) {
    if (a < 0 || b < 0 || a >= shadow.size.x || b >= shadow.size.y) return 1.0;  // past the casters
    return z <= double(shadow.depth[size_t(b) * size_t(shadow.size.x) + size_t(a)]) ? 1.0 : 0.0;
  };
  return (1 - fy) * ((1 - fx) * lit(i, j) + fx * lit(i + 1, j)) + fy * ((1 - fx) * lit(i, j + 1) + fx * lit(i + 1, j + 1));
}

double mesh_shadow_depth(const MeshShadow& shadow, const glm::vec3& p, double bias_texels) {
  const double visible = mesh_visibility(shadow, p, bias_texels);
  return visible >= 1.0 ? 0.0 : std::min(-std::log(std::max(visible, 0.0)), kMeshShadowDepth);
}

namespace {

// What the grid depends on: the light, the size and every instance's mesh and placement.
std::vector<double> grid_inputs(const std::vector<MeshInstance>& instances, const glm::vec3& travel, int across) {
  std::vector<double> k = {travel.x, travel.y, travel.z, double(across)};
  for (const MeshInstance& m : instances) {
    const glm::mat4 model = m.placement.model_matrix();
    k.push_back(m.geometry ? double(m.geometry->id) : 0.0);
    k.push_back(double(m.kind));
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) k.push_back(model[c][r]);
  }
  return k;
}

struct MeshShadowInputs {
  std::vector<double> last;
};

void run_mesh_shadow(ecs::World& world) {
  MeshShadow& shadow = world.resource<MeshShadow>();
  const ShadowSettings* settings = world.try_resource<const ShadowSettings>();
  const SceneLighting* lighting = world.try_resource<const SceneLighting>();
  std::vector<MeshInstance> instances;
  world.each<const MeshInstance>([&](const MeshInstance& m) { instances.push_back(m); });
  const bool wanted = settings && settings->method != ShadowMethod::none && lighting && lighting->key_shines() &&
                      std::any_of(instances.begin(), instances.end(), [](const MeshInstance& m) {
                        return m.geometry && casts_shadow(m.kind);
                      });
  MeshShadowInputs& inputs = world.resource<MeshShadowInputs>();
  if (!wanted) {
    inputs.last.clear();
    if (!shadow.empty()) shadow = MeshShadow{{}, {}, {}, 0.0f, shadow.version + 1};
    return;
  }
  std::vector<double> now = grid_inputs(instances, lighting->key()->travel, settings->mesh_map_size);
  if (now == inputs.last && !shadow.empty()) return;
  build_mesh_shadow_map(instances, glm::dvec3(lighting->key()->travel), settings->mesh_map_size, shadow);
  inputs.last = std::move(now);
}

}  // namespace

ecs::SystemDesc mesh_shadow_system() {
  return {.name = "mesh_shadow",
          .phase = ecs::Phase::light,
          .access = ecs::Access::of<ecs::Reads<MeshInstance, ShadowSettings, SceneLighting>,
                                    ecs::Writes<MeshShadow, MeshShadowInputs>>(),
          .run = run_mesh_shadow,
          .setup =
              [](ecs::World& world) {
                if (!world.has_resource<MeshShadow>()) world.set_resource<MeshShadow>();
                if (!world.has_resource<MeshShadowInputs>()) world.set_resource<MeshShadowInputs>();
              },
          .after = {"lighting"}};
}

}  // namespace pyro
