#include "systems/reference/particle_reference.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <numbers>
#include <vector>

#include <glm/geometric.hpp>

#include "systems/reference/grid_sampling.h"
#include "systems/reference/parallel_rows.h"
#include "systems/reference/pixel_ray.h"
#include "systems/reference/ray_pieces.h"

namespace pyro {

namespace {

constexpr double kExtent = 3.0;

struct Gaussian {
  glm::dvec3 c, col;
  double s = 1, k = 0;
};

Gaussian make_gaussian(const glm::dvec3& c, double radius, double density, const glm::dvec3& col) {
  Gaussian g;
  g.c = c;
  g.col = col;
  g.s = radius / kExtent;
  const double rho = std::min(density, 1.0 - 1e-12);
  const double tau0 = -std::log1p(-rho);
  // Optical depth through the centre of the clamped kernel: k s sqrt(2 pi) erf(3 / sqrt 2).
  g.k = tau0 / (g.s * std::sqrt(2.0 * std::numbers::pi) * std::erf(kExtent / std::numbers::sqrt2));
  return g;
}

// Where the ray o + t w is inside the particle's cube; false if nowhere.
bool cube_span(const Gaussian& g, const glm::dvec3& o, const glm::dvec3& w, double& a, double& b) {
  const double h = kExtent * g.s;
  const double oo[3] = {o.x, o.y, o.z}, ww[3] = {w.x, w.y, w.z};
  const double lo[3] = {g.c.x - h, g.c.y - h, g.c.z - h}, hi[3] = {g.c.x + h, g.c.y + h, g.c.z + h};
  return intersect_box(oo, ww, lo, hi, a, b);
}

double depth_between(const Gaussian& g, const glm::dvec3& o, const glm::dvec3& w, double a, double b) {
  const glm::dvec3 oc = g.c - o;
  const double tc = glm::dot(oc, w);
  const double d2 = glm::dot(oc, oc) - tc * tc;
  const double q = 1.0 / (g.s * std::numbers::sqrt2);
  return g.k * std::exp(-std::max(d2, 0.0) / (2.0 * g.s * g.s)) * g.s *
         std::sqrt(std::numbers::pi / 2.0) * (std::erf((b - tc) * q) - std::erf((a - tc) * q));
}

}  // namespace

double particle_optical_depth(const glm::dvec3& centre, double radius, double density,
                              const glm::dvec3& o, const glm::dvec3& w, double a, double b) {
  const Gaussian g = make_gaussian(centre, radius, density, glm::dvec3(0));
  double ca, cb;
  if (!cube_span(g, o, w, ca, cb)) return 0.0;
  a = std::max(a, ca);
  b = std::min(b, cb);
  return b > a ? depth_between(g, o, w, a, b) : 0.0;
}

namespace {

// The shared ray integration: `behind(x, y)` is what the ray sees after the medium and
// `stop(x, y)` the distance along it where an opaque surface ends it.
template <class Behind, class Stop>
RgbImage integrate_particles(const ParticlePool& p, const CameraFrame& camera, Behind&& behind,
                             Stop&& stop, int threads, double max_piece_depth) {
  std::vector<Gaussian> gs;
  gs.reserve(p.size());
  for (size_t i = 0; i < p.size(); ++i)
    if (p.density[i] > 0.0f)
      gs.push_back(make_gaussian({p.px[i], p.py[i], p.pz[i]}, p.radius[i], p.density[i],
                                 {p.r[i], p.g[i], p.b[i]}));
  RgbImage img;
  img.width = camera.width;
  img.height = camera.height;
  img.rgb.assign(size_t(3) * img.width * img.height, 0.0f);
  const glm::dvec3 eye(camera.eye);
  parallel_rows(img.height, threads, [&](int y) {
    RayPieces pieces;
    for (int x = 0; x < img.width; ++x) {
      const glm::dvec3 w = pixel_ray_direction(camera, x + 0.5, y + 0.5);
      const double t_stop = stop(x, y);
      pieces.clear();
      for (size_t i = 0; i < gs.size(); ++i) {
        double a, b;
        if (!cube_span(gs[i], eye, w, a, b)) continue;
        a = std::max(a, 0.0);
        b = std::min(b, t_stop);
        if (b <= a) continue;
        pieces.add(a, b, glm::dot(gs[i].c - eye, w), i);
      }
      const glm::dvec3 L = pieces.integrate(
          [&](size_t i, double a, double b) { return depth_between(gs[i], eye, w, a, b); },
          [&](size_t i) { return gs[i].col; }, behind(x, y), max_piece_depth);
      float* px = img.at(x, y);
      px[0] = float(L.x);
      px[1] = float(L.y);
      px[2] = float(L.z);
    }
  });
  return img;
}

}  // namespace

RgbImage render_particles_reference(const ParticlePool& p, const CameraFrame& camera,
                                    const glm::dvec3& background, int threads,
                                    double max_piece_depth) {
  return integrate_particles(
      p, camera, [&](int, int) { return background; },
      [](int, int) { return std::numeric_limits<double>::infinity(); }, threads, max_piece_depth);
}

RgbImage render_particles_reference_over(const ParticlePool& p, const CameraFrame& camera,
                                         const RgbImage& behind, const std::vector<float>& stop,
                                         int threads, double max_piece_depth) {
  const size_t pixels = static_cast<size_t>(camera.width) * camera.height;
  if (behind.width != camera.width || behind.height != camera.height || stop.size() != pixels)
    throw std::invalid_argument("render_particles_reference_over: image sizes differ from the camera's");
  return integrate_particles(
      p, camera,
      [&](int x, int y) {
        const float* c = behind.at(x, y);
        return glm::dvec3(c[0], c[1], c[2]);
      },
      [&](int x, int y) { return double(stop[static_cast<size_t>(y) * camera.width + x]); }, threads,
      max_piece_depth);
}

std::vector<float> ray_stop_distances(const CameraFrame& camera, const std::vector<float>& depth) {
  const size_t pixels = static_cast<size_t>(camera.width) * camera.height;
  if (depth.size() != pixels)
    throw std::invalid_argument("ray_stop_distances: depth image size differs from the camera's");
  std::vector<float> out(pixels);
  const double n = camera.near, f = camera.far;
  for (int y = 0; y < camera.height; ++y)
    for (int x = 0; x < camera.width; ++x) {
      const size_t i = static_cast<size_t>(y) * camera.width + x;
      const double d = depth[i];
      if (d >= 1.0) {
        out[i] = std::numeric_limits<float>::infinity();
        continue;
      }
      // Window depth d -> NDC z = 2d - 1 -> view depth 2nf / (f + n - z (f - n)) (the inverse
      // of glm::perspective's depth mapping), then along the ray: view depth / cos(angle).
      const double z_ndc = 2.0 * d - 1.0;
      const double view_depth = 2.0 * n * f / (f + n - z_ndc * (f - n));
      const glm::dvec3 w = pixel_ray_direction(camera, x + 0.5, y + 0.5);
      out[i] = float(view_depth / glm::dot(w, glm::dvec3(camera.forward)));
    }
  return out;
}

}  // namespace pyro
