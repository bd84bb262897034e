#include "systems/shadowing/opacity_shadow_map.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <glm/geometric.hpp>
#include <tbb/parallel_for.h>

#include "engine/math/light_space_texture.h"
#include "engine/math/shadow_ray_index.h"
#include "engine/math/tabulated_erf.h"

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

// A particle's footprint on the map: texel columns [i0, i1] x [j0, j1], clamped to the map and
// to rows [j_begin, j_end).
struct Footprint {
  int i0, i1, j0, j1;
  bool empty() const { return i0 > i1 || j0 > j1; }
};

// How far the caster reaches from its centre across the light along the unit axis `a`: a
// Gaussian's cube of half-width 3 s projects to 3 s (|a.x| + |a.y| + |a.z|); the others reach
// caster_reach every way.
double reach_along(const ShadowCaster& g, const glm::dvec3& a) {
  if (g.shape != CasterShape::gaussian) return caster_reach(g);
  return kGaussianCubeHalfWidth * g.size * (std::abs(a.x) + std::abs(a.y) + std::abs(a.z));
}

Footprint footprint(const ShadowCaster& g, const MapFrame& f, int j_begin, int j_end) {
  const double eu = reach_along(g, f.u), ev = reach_along(g, f.v);
  const double cu = glm::dot(g.c, f.u) - f.u0, cv = glm::dot(g.c, f.v) - f.v0;
  return {std::max(0, int(std::floor((cu - eu) / f.du - 0.5))),
          std::min(f.nu - 1, int(std::ceil((cu + eu) / f.du - 0.5))),
          std::max(j_begin, int(std::floor((cv - ev) / f.du - 0.5))),
          std::min(j_end - 1, int(std::ceil((cv + ev) / f.du - 0.5)))};
}

glm::dvec3 column_origin(const MapFrame& f, int i, int j) {
  return (f.u0 + (i + 0.5) * f.du) * f.u + (f.v0 + (j + 0.5) * f.du) * f.v + f.w0 * f.w;
}

// Where the map's columns cross a Gaussian's cube (|p - c| <= h on every axis; the slab method of
// gaussian_cube_span, Kay & Kajiya 1986) with the divisions done once: a column through
// o = x u + y v + w0 w meets axis a's slab over t in [m - r, m + r], m = (c_a - o_a) / w_a linear in
// (x, y) and r = h / |w_a|; an axis the light runs across (w_a = 0) holds the column when
// |x u_a + y v_a - c_a| <= h.
class CubeColumns {
 public:
  CubeColumns(const ShadowCaster& g, const MapFrame& f) {
    const double h = kGaussianCubeHalfWidth * g.size;
    for (int a = 0; a < 3; ++a) {
      across_[a] = f.w[a] == 0.0;
      const double inv = across_[a] ? 1.0 : 1.0 / f.w[a];
      base_[a] = across_[a] ? -g.c[a] : (g.c[a] - f.w0 * f.w[a]) * inv;
      per_x_[a] = across_[a] ? f.u[a] : -f.u[a] * inv;
      per_y_[a] = across_[a] ? f.v[a] : -f.v[a] * inv;
      half_[a] = across_[a] ? h : h * std::abs(inv);
    }
  }
  // The span [a, b] of the column at (x, y) inside the cube; false if it misses.
  bool span(double x, double y, double& a, double& b) const {
    a = -std::numeric_limits<double>::max();
    b = std::numeric_limits<double>::max();
    for (int k = 0; k < 3; ++k) {
      const double m = base_[k] + x * per_x_[k] + y * per_y_[k];
      if (across_[k]) {
        if (std::abs(m) > half_[k]) return false;
        continue;
      }
      a = std::max(a, m - half_[k]);
      b = std::min(b, m + half_[k]);
    }
    return a < b;
  }

 private:
  double base_[3], per_x_[3], per_y_[3], half_[3];
  bool across_[3];
};

// What a Gaussian's columns share (gaussian_line_integral.h, gaussian_ray_profile: its depth along
// a line over [a, b] is A (erf((b - tc) q) - erf((a - tc) q)), A = k exp(-d^2 / (2 s^2)) s sqrt(pi / 2),
// q = 1 / (s sqrt 2)). The columns run along the light, so the closest approach tc is the same in
// every one, and erf((t_k - tc) q) at each slice centre t_k is one table; d^2 is the column's
// offset across the light, whose exponential is the product of one per texel column (across_u)
// and one per texel row (across_v, with the rest of A).
struct GaussianColumns {
  double tc = 0.0, q = 1.0;
  int k0 = 0;  // slice_erf[k - k0] for the slices within the cube's reach of tc
  std::vector<double> across_u, across_v, slice_erf;
  void fit(const ShadowCaster& g, const MapFrame& f, const Footprint& fp);
  double erf_at_slice(int k, const MapFrame& f) const {
    const size_t n = size_t(k - k0);
    return k >= k0 && n < slice_erf.size() ? slice_erf[n] : tabulated_erf(((k + 0.5) * f.dw - tc) * q);
  }
};

void GaussianColumns::fit(const ShadowCaster& g, const MapFrame& f, const Footprint& fp) {
  const double s = g.size, falloff = 1.0 / (2.0 * s * s);
  q = 1.0 / (s * std::numbers::sqrt2);
  tc = glm::dot(g.c, f.w) - f.w0;
  const double cu = glm::dot(g.c, f.u), cv = glm::dot(g.c, f.v);
  const double peak = g.k * s * std::sqrt(std::numbers::pi / 2.0);
  across_u.resize(size_t(fp.i1 - fp.i0 + 1));
  across_v.resize(size_t(fp.j1 - fp.j0 + 1));
  for (int i = fp.i0; i <= fp.i1; ++i) {
    const double d = cu - (f.u0 + (i + 0.5) * f.du);
    across_u[size_t(i - fp.i0)] = std::exp(-d * d * falloff);
  }
  for (int j = fp.j0; j <= fp.j1; ++j) {
    const double d = cv - (f.v0 + (j + 0.5) * f.du);
    across_v[size_t(j - fp.j0)] = peak * std::exp(-d * d * falloff);
  }
  const double e = caster_reach(g);
  k0 = std::max(0, int(std::ceil((tc - e) / f.dw - 0.5)));
  const int k1 = std::min(f.nw - 1, int(std::floor((tc + e) / f.dw - 0.5)));
  slice_erf.resize(size_t(std::max(0, k1 - k0 + 1)));
  for (int k = k0; k <= k1; ++k) slice_erf[size_t(k - k0)] = tabulated_erf(((k + 0.5) * f.dw - tc) * q);
}

// A Gaussian's optical depth added as splat_rows adds it, each column costing the erf at its
// entry into the cube and at its exit, read from a table (engine/math/tabulated_erf.h, within
// 1.2e-7 of erf).
void splat_gaussian_rows(const ShadowCaster& g, const MapFrame& f, const Footprint& fp,
                         std::vector<float>& depth, std::vector<float>& steps, GaussianColumns& t) {
  t.fit(g, f, fp);
  const CubeColumns cube(g, f);
  for (int j = fp.j0; j <= fp.j1; ++j)
    for (int i = fp.i0; i <= fp.i1; ++i) {
      double a, b;
      if (!cube.span(f.u0 + (i + 0.5) * f.du, f.v0 + (j + 0.5) * f.du, a, b)) continue;
      a = std::max(a, 0.0);
      const double amplitude = t.across_v[size_t(j - fp.j0)] * t.across_u[size_t(i - fp.i0)];
      const double entry = tabulated_erf((a - t.tc) * t.q);
      const size_t column = (size_t(j) * size_t(f.nu) + size_t(i)) * size_t(f.nw);
      int k = std::max(0, int(std::ceil(a / f.dw - 0.5)));
      for (; k < f.nw && (k + 0.5) * f.dw < b; ++k)
        depth[column + size_t(k)] += float(amplitude * (t.erf_at_slice(k, f) - entry));
      if (k < f.nw) steps[column + size_t(k)] += float(amplitude * (tabulated_erf((b - t.tc) * t.q) - entry));
    }
}

// One particle's optical depth added to the texel columns of rows [j_begin, j_end): where a
// column's ray enters the particle (a Gaussian's cube, a sphere) at a and leaves at b, the slices
// inside get the depth over [a, t_k] and the first slice past b steps up by the whole [a, b]
// (summed along the columns afterwards). `depth` and `steps` hold each column's slices one
// after another (texel * nw + k), so that a particle's updates along a column are adjacent.
void splat_rows(const ShadowCaster& g, const MapFrame& f, int j_begin, int j_end,
                std::vector<float>& depth, std::vector<float>& steps, GaussianColumns& tables) {
  const Footprint fp = footprint(g, f, j_begin, j_end);
  if (fp.empty()) return;
  if (g.shape == CasterShape::gaussian) return splat_gaussian_rows(g, f, fp, depth, steps, tables);
  for (int j = fp.j0; j <= fp.j1; ++j)
    for (int i = fp.i0; i <= fp.i1; ++i) {
      const glm::dvec3 o = column_origin(f, i, j);
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
  constexpr int kRowsPerStrip = 2;
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
    GaussianColumns tables;
    for (uint32_t p : reaching[size_t(s)]) splat_rows(particles[p], f, j_begin, j_end, depth, steps, tables);
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
