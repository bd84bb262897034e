#include "systems/runtime/reference/particle_sets_reference.h"

#include <algorithm>
#include <stdexcept>
#include <variant>

#include <glm/geometric.hpp>

#include "engine/math/gaussian_line_integral.h"
#include "engine/math/sphere_line_integral.h"
#include "systems/runtime/reference/parallel_rows.h"
#include "systems/runtime/reference/pixel_ray.h"
#include "systems/runtime/reference/ray_pieces.h"

namespace pyro {

namespace {

// One particle of any kind: its field and its colour.
struct ReferenceParticle {
  std::variant<ClampedGaussian, ConeSphere> field;
  glm::dvec3 colour;
};

std::vector<ReferenceParticle> reference_particles(const std::vector<ReferenceParticleSet>& sets) {
  std::vector<ReferenceParticle> out;
  for (const ReferenceParticleSet& set : sets) {
    if (set.shape == ParticleShape::planar)
      throw std::invalid_argument("render_particle_sets_reference: planar billboards have no reference field");
    const ParticlePool& p = *set.pool;
    for (size_t i = 0; i < p.size(); ++i) {
      if (!(p.density[i] > 0.0f)) continue;
      const glm::dvec3 c(p.px[i], p.py[i], p.pz[i]);
      const glm::dvec3 colour(p.r[i], p.g[i], p.b[i]);
      if (set.shape == ParticleShape::gaussian)
        out.push_back({clamped_gaussian(c, p.radius[i], p.density[i]), colour});
      else
        out.push_back({ConeSphere{c, p.radius[i], p.density[i]}, colour});
    }
  }
  return out;
}

// The particle's span along eye + t w and its closest approach; false if the ray misses it.
bool particle_span(const ReferenceParticle& p, const glm::dvec3& eye, const glm::dvec3& w, double& a,
                   double& b, double& closest) {
  if (const auto* g = std::get_if<ClampedGaussian>(&p.field)) {
    closest = glm::dot(g->c - eye, w);
    return gaussian_cube_span(*g, eye, w, a, b);
  }
  const ConeSphere& s = std::get<ConeSphere>(p.field);
  closest = glm::dot(s.c - eye, w);
  double extinction = 0.0;
  return sphere_chord(s, eye, w, a, b, extinction);
}

double particle_depth(const ReferenceParticle& p, const glm::dvec3& eye, const glm::dvec3& w, double a,
                      double b) {
  if (const auto* g = std::get_if<ClampedGaussian>(&p.field)) return gaussian_depth_between(*g, eye, w, a, b);
  return sphere_optical_depth(std::get<ConeSphere>(p.field), eye, w, a, b);
}

}  // namespace

RgbImage render_particle_sets_reference(const std::vector<ReferenceParticleSet>& sets,
                                        const CameraFrame& camera, const glm::dvec3& background,
                                        int threads, double max_piece_depth) {
  const std::vector<ReferenceParticle> particles = reference_particles(sets);
  RgbImage img;
  img.width = camera.width;
  img.height = camera.height;
  img.rgb.assign(size_t(3) * img.width * img.height, 0.0f);
  const glm::dvec3 eye(camera.eye);
  parallel_rows(img.height, threads, [&](int y) {
    RayPieces pieces;
    for (int x = 0; x < img.width; ++x) {
      const glm::dvec3 w = pixel_ray_direction(camera, x + 0.5, y + 0.5);
      pieces.clear();
      for (size_t i = 0; i < particles.size(); ++i) {
        double a = 0.0, b = 0.0, closest = 0.0;
        if (!particle_span(particles[i], eye, w, a, b, closest)) continue;
        a = std::max(a, 0.0);
        if (b > a) pieces.add(a, b, closest, i);
      }
      const glm::dvec3 L = pieces.integrate(
          [&](size_t i, double a, double b) { return particle_depth(particles[i], eye, w, a, b); },
          [&](size_t i) { return particles[i].colour; }, background, max_piece_depth);
      float* px = img.at(x, y);
      px[0] = float(L.x);
      px[1] = float(L.y);
      px[2] = float(L.z);
    }
  });
  return img;
}

}  // namespace pyro
