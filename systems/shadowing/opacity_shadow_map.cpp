#include "systems/shadowing/opacity_shadow_map.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>
#include <tbb/parallel_for.h>

#include "engine/math/light_space_texture.h"
#include "engine/math/shadow_ray_index.h"

namespace pyro {

namespace {

// The map's light-space frame: texel (i, j, k) is centred at
// (u0 + (i + 0.5) du) u + (v0 + (j + 0.5) du) v + (w0 + (k + 0.5) dw) w.
struct MapFrame {
  glm::dvec3 u, v, w;
  double u0 = 0, v0 = 0, w0 = 0, du = 1, dw = 1;
  int nu = 0, nv = 0, nw = 0;
};

MapFrame fit_frame(const std::vector<ShadowCaster>& gs, const glm::dvec3& light_travel,
                   ShadowMapSize size) {
  MapFrame f;
  f.w = glm::normalize(light_travel);
  orthonormal_basis(-f.w, f.u, f.v);
  glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
  for (const ShadowCaster& g : gs) {
    const glm::dvec3 c(glm::dot(g.c, f.u), glm::dot(g.c, f.v), glm::dot(g.c, f.w));
    lo = glm::min(lo, c - caster_reach(g));
    hi = glm::max(hi, c + caster_reach(g));
  }
  const glm::dvec3 extent = glm::max(hi - lo, glm::dvec3(1e-6));
  const int across = std::max(size.across, 4), slices = std::max(size.slices, 4);
  f.du = std::max(extent.x, extent.y) / (across - 2);
  f.nu = int(std::ceil(extent.x / f.du)) + 2;
  f.nv = int(std::ceil(extent.y / f.du)) + 2;
  f.dw = extent.z / (slices - 2);
  f.nw = slices;
  f.u0 = lo.x - f.du;
  f.v0 = lo.y - f.du;
  f.w0 = lo.z - f.dw;
  return f;
}

glm::mat4 world_to_texture(const MapFrame& f) {
  return light_space_texture(f.u, f.v, f.w, {f.u0, f.v0, f.w0}, {f.nu * f.du, f.nv * f.du, f.nw * f.dw});
}

// One particle's optical depth added to the texel columns of rows [j_begin, j_end): where a
// column's ray enters the particle (a Gaussian's cube, a sphere) at a and leaves at b, the slices
// inside get the depth over [a, t_k] and the first slice past b steps up by the whole [a, b]
// (summed along the columns afterwards). `depth` and `steps` hold each column's slices one
// after another (texel * nw + k), so that a particle's updates along a column are adjacent.
void splat_rows(const ShadowCaster& g, const MapFrame& f, int j_begin, int j_end,
                std::vector<float>& depth, std::vector<float>& steps) {
  const double e = caster_reach(g);
  const double cu = glm::dot(g.c, f.u) - f.u0, cv = glm::dot(g.c, f.v) - f.v0;
  const int i0 = std::max(0, int(std::floor((cu - e) / f.du - 0.5)));
  const int i1 = std::min(f.nu - 1, int(std::ceil((cu + e) / f.du - 0.5)));
  const int j0 = std::max(j_begin, int(std::floor((cv - e) / f.du - 0.5)));
  const int j1 = std::min(j_end - 1, int(std::ceil((cv + e) / f.du - 0.5)));
  for (int j = j0; j <= j1; ++j)
    for (int i = i0; i <= i1; ++i) {
      const glm::dvec3 o = (f.u0 + (i + 0.5) * f.du) * f.u + (f.v0 + (j + 0.5) * f.du) * f.v + f.w0 * f.w;
      double a, b;
      if (!caster_span(g, o, f.w, a, b)) continue;
      a = std::max(a, 0.0);
      const size_t column = (size_t(j) * size_t(f.nu) + size_t(i)) * size_t(f.nw);
      const CasterRayProfile ray = caster_ray_profile(g, o, f.w);
      const double entry = ray.cumulative(a);
      int k = std::max(0, int(std::ceil(a / f.dw - 0.5)));
      for (; k < f.nw && (k + 0.5) * f.dw < b; ++k)
        depth[column + size_t(k)] += float(ray.cumulative((k + 0.5) * f.dw) - entry);
      if (k < f.nw) steps[column + size_t(k)] += float(ray.cumulative(b) - entry);
    }
}

}  // namespace

void build_opacity_shadow_map(const std::vector<ShadowCaster>& particles,
                              const glm::dvec3& light_travel, ShadowMapSize size, ShadowVolume& out) {
  ++out.version;
  out.optical_depth.clear();
  out.size = glm::ivec3(0);
  if (particles.empty()) return;
  const MapFrame f = fit_frame(particles, light_travel, size);
  const size_t plane = size_t(f.nu) * size_t(f.nv);
  out.size = {f.nu, f.nv, f.nw};
  out.world_to_texture = world_to_texture(f);
  out.optical_depth.assign(plane * size_t(f.nw), 0.0f);
  std::vector<float> depth(out.optical_depth.size(), 0.0f), steps(out.optical_depth.size(), 0.0f);
  // Strips of rows, each splatted by one task from the particles that reach it (in their order,
  // so the sums do not depend on the threads).
  constexpr int kRowsPerStrip = 4;
  const int strips = (f.nv + kRowsPerStrip - 1) / kRowsPerStrip;
  std::vector<std::vector<uint32_t>> reaching(static_cast<size_t>(strips));
  for (size_t p = 0; p < particles.size(); ++p) {
    const double cv = glm::dot(particles[p].c, f.v) - f.v0, e = caster_reach(particles[p]);
    const int s0 = std::clamp(int(std::floor((cv - e) / f.du - 0.5)) / kRowsPerStrip, 0, strips - 1);
    const int s1 = std::clamp(int(std::ceil((cv + e) / f.du - 0.5)) / kRowsPerStrip, 0, strips - 1);
    for (int s = s0; s <= s1; ++s) reaching[size_t(s)].push_back(uint32_t(p));
  }
  tbb::parallel_for(0, strips, [&](int s) {
    const int j_begin = s * kRowsPerStrip, j_end = std::min(f.nv, j_begin + kRowsPerStrip);
    for (uint32_t p : reaching[size_t(s)]) splat_rows(particles[p], f, j_begin, j_end, depth, steps);
    // The whole columns of the particles a column has passed, summed along it, into the map's
    // layout (slice after slice).
    for (int j = j_begin; j < j_end; ++j)
      for (int i = 0; i < f.nu; ++i) {
        const size_t texel = size_t(j) * size_t(f.nu) + size_t(i), column = texel * size_t(f.nw);
        float passed = 0.0f;
        for (int k = 0; k < f.nw; ++k) {
          passed += steps[column + size_t(k)];
          out.optical_depth[texel + size_t(k) * plane] = depth[column + size_t(k)] + passed;
        }
      }
  });
}

float sample_optical_depth(const ShadowVolume& map, const glm::vec3& p) {
  if (map.empty()) return 0.0f;
  const glm::vec4 t = map.world_to_texture * glm::vec4(p, 1.0f);
  int i0[3], i1[3];
  float frac[3];
  for (int a = 0; a < 3; ++a) {
    const float x = t[a] * float(map.size[a]) - 0.5f;
    const float fl = std::floor(x);
    frac[a] = x - fl;
    i0[a] = std::clamp(int(fl), 0, map.size[a] - 1);
    i1[a] = std::clamp(int(fl) + 1, 0, map.size[a] - 1);
  }
  auto at = [&](int x, int y, int z) {
    return map.optical_depth[(size_t(z) * size_t(map.size.y) + size_t(y)) * size_t(map.size.x) + size_t(x)];
  };
  float result = 0.0f;
  for (int c = 0; c < 8; ++c) {
    const int x = c & 1 ? i1[0] : i0[0], y = c & 2 ? i1[1] : i0[1], z = c & 4 ? i1[2] : i0[2];
    const float wgt = (c & 1 ? frac[0] : 1 - frac[0]) * (c & 2 ? frac[1] : 1 - frac[1]) *
                      (c & 4 ? frac[2] : 1 - frac[2]);
    result += wgt * at(x, y, z);
  }
  return result;
}

}  // namespace pyro
