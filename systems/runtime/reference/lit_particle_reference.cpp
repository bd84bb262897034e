#include "systems/runtime/reference/lit_particle_reference.h"

#include <cmath>
#include <stdexcept>
#include <utility>

#include <glm/geometric.hpp>

#include "engine/math/phase_function.h"
#include "engine/math/shadow_ray_index.h"
#include "systems/runtime/reference/parallel_rows.h"
#include "systems/runtime/reference/particle_reference.h"
#include "systems/runtime/reference/pixel_ray.h"
#include "systems/runtime/reference/ray_pieces.h"

namespace pyro {

namespace {

std::vector<ShadowCaster> casters(const ParticlePool& p) {
  std::vector<ShadowCaster> gs;
  for (size_t i = 0; i < p.size(); ++i)
    if (p.density[i] > 0.0f) gs.push_back(clamped_gaussian({p.px[i], p.py[i], p.pz[i]}, p.radius[i], p.density[i]));
  return gs;
}

void require_camera_size(const CameraFrame& camera, const RgbImage& image, const std::vector<float>& stop,
                         const char* what) {
  const size_t pixels = static_cast<size_t>(camera.width) * camera.height;
  if (image.width != camera.width || image.height != camera.height || stop.size() != pixels)
    throw std::invalid_argument(std::string(what) + ": image sizes differ from the camera's");
}

// The point lights' light scattered at x toward the eye (`to_eye`, unit).
glm::dvec3 point_light_scattering(const ReferenceSun& sun, const glm::dvec3& x, const glm::dvec3& to_eye) {
  glm::dvec3 sum(0.0);
  for (const PointEmitter& l : sun.point_lights) {
    const glm::dvec3 travel = x - l.position;
    const double d2 = glm::dot(travel, travel);
    const double mu = d2 > 0.0 ? glm::dot(travel, to_eye) / std::sqrt(d2) : 0.0;
    sum += l.intensity * henyey_greenstein(mu, sun.scattering.anisotropy) / std::max(d2, l.radius * l.radius);
  }
  return sum;
}

}  // namespace

RgbImage shadowed_opaque_reference(const ParticlePool& particles, const CameraFrame& camera,
                                   const ReferenceSun& sun, const RgbImage& sunlit,
                                   const RgbImage& sunless, const std::vector<float>& stop, int threads) {
  return shadowed_opaque_reference(casters(particles), camera, sun, sunlit, sunless, stop, threads);
}

RgbImage shadowed_opaque_reference(std::vector<ShadowCaster> casters, const CameraFrame& camera,
                                   const ReferenceSun& sun, const RgbImage& sunlit,
                                   const RgbImage& sunless, const std::vector<float>& stop, int threads) {
  require_camera_size(camera, sunlit, stop, "shadowed_opaque_reference");
  require_camera_size(camera, sunless, stop, "shadowed_opaque_reference");
  const ShadowRayIndex index(std::move(casters), sun.travel);
  RgbImage out = sunlit;
  const glm::dvec3 eye(camera.eye);
  parallel_rows(camera.height, threads, [&](int y) {
    for (int x = 0; x < camera.width; ++x) {
      const double t = stop[static_cast<size_t>(y) * camera.width + x];
      if (!std::isfinite(t)) continue;
      const glm::dvec3 p = eye + t * pixel_ray_direction(camera, x + 0.5, y + 0.5);
      const double transmittance = std::exp(-index.optical_depth_to_light(p) - sun.mesh_surface_depth_at(p));
      for (int c = 0; c < 3; ++c)
        out.at(x, y)[c] = float(sunless.at(x, y)[c] + transmittance * (sunlit.at(x, y)[c] - sunless.at(x, y)[c]));
    }
  });
  return out;
}

RgbImage render_lit_particles_reference_over(const ParticlePool& p, const CameraFrame& camera,
                                             const ReferenceSun& sun, const RgbImage& behind,
                                             const std::vector<float>& stop, int threads,
                                             double max_piece_depth) {
  require_camera_size(camera, behind, stop, "render_lit_particles_reference_over");
  std::vector<ClampedGaussian> gs;
  std::vector<glm::dvec3> albedo;
  for (size_t i = 0; i < p.size(); ++i)
    if (p.density[i] > 0.0f) {
      gs.push_back(clamped_gaussian({p.px[i], p.py[i], p.pz[i]}, p.radius[i], p.density[i]));
      albedo.push_back({p.r[i], p.g[i], p.b[i]});
    }
  const ShadowRayIndex index(std::vector<ShadowCaster>(gs.begin(), gs.end()), sun.travel);
  RgbImage img = behind;
  const glm::dvec3 eye(camera.eye), travel = glm::normalize(sun.travel);
  parallel_rows(img.height, threads, [&](int y) {
    RayPieces pieces;
    for (int x = 0; x < img.width; ++x) {
      const glm::dvec3 w = pixel_ray_direction(camera, x + 0.5, y + 0.5);
      const double mu = -glm::dot(travel, w);
      const double t_stop = stop[static_cast<size_t>(y) * camera.width + x];
      add_particle_pieces(gs, eye, w, t_stop, pieces);
      const float* back = behind.at(x, y);
      const glm::dvec3 L = pieces.integrate(
          [&](size_t i, double a, double b) { return gaussian_depth_between(gs[i], eye, w, a, b); },
          [&](size_t i) { return albedo[i]; }, glm::dvec3(back[0], back[1], back[2]), max_piece_depth,
          [&](double a, double b) {
            const glm::dvec3 mid = eye + 0.5 * (a + b) * w;
            const double tau = index.optical_depth_to_light(mid) + sun.mesh_depth_at(mid);
            return sun.color * sun_scattering(sun.scattering, mu, tau) + sun.ambient +
                   point_light_scattering(sun, mid, -w);
          });
      float* px = img.at(x, y);
      for (int c = 0; c < 3; ++c) px[c] = float(L[c]);
    }
  });
  return img;
}

}  // namespace pyro
