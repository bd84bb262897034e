#include "systems/runtime/reference/particle_reference.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include <glm/geometric.hpp>

#include "engine/math/gaussian_line_integral.h"
#include "systems/runtime/reference/parallel_rows.h"
#include "systems/runtime/reference/pixel_ray.h"
#include "systems/runtime/reference/ray_pieces.h"

namespace pyro {

double particle_optical_depth(const glm::dvec3& centre, double radius, double density,
                              const glm::dvec3& o, const glm::dvec3& w, double a, double b) {
  return gaussian_optical_depth(clamped_gaussian(centre, radius, density), o, w, a, b);
}

void add_particle_pieces(const std::vector<ClampedGaussian>& gs, const glm::dvec3& eye,
                         const glm::dvec3& w, double t_stop, RayPieces& pieces) {
  pieces.clear();
  for (size_t i = 0; i < gs.size(); ++i) {
    double a, b;
    if (!gaussian_cube_span(gs[i], eye, w, a, b)) continue;
    a = std::max(a, 0.0);
    b = std::min(b, t_stop);
    if (b <= a) continue;
    pieces.add(a, b, glm::dot(gs[i].c - eye, w), i);
  }
}

namespace {

// The shared ray integration: `behind(x, y)` is what the ray sees after the medium and
// `stop(x, y)` the distance along it where an opaque surface ends it.
template <class Behind, class Stop>
RgbImage integrate_particles(const ParticlePool& p, const CameraFrame& camera, Behind&& behind,
                             Stop&& stop, int threads, double max_piece_depth) {
  std::vector<ClampedGaussian> gs;
  std::vector<glm::dvec3> colours;
  gs.reserve(p.size());
  for (size_t i = 0; i < p.size(); ++i)
    if (p.density[i] > 0.0f) {
      gs.push_back(clamped_gaussian({p.px[i], p.py[i], p.pz[i]}, p.radius[i], p.density[i]));
      colours.push_back({p.r[i], p.g[i], p.b[i]});
    }
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
      add_particle_pieces(gs, eye, w, t_stop, pieces);
      const glm::dvec3 L = pieces.integrate(
          [&](size_t i, double a, double b) { return gaussian_depth_between(gs[i], eye, w, a, b); },
          [&](size_t i) { return colours[i]; }, behind(x, y), max_piece_depth);
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
