#include "systems/cloud_import/scene_volume.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <glm/geometric.hpp>

#include "engine/core/user_error.h"
#include "engine/io/particle_file.h"
#include "engine/io/vdb_reader.h"
#include "systems/cloud_import/cloud_import.h"
#include "systems/lighting/lighting_system.h"

namespace pyro {

namespace {

// p' = at + scale (p - anchor), from the entry's placement and the particles' centres.
struct Placement {
  glm::dvec3 at{0.0}, anchor{0.0};
  double scale = 1.0;
  glm::dvec3 apply(const glm::dvec3& p) const { return at + scale * (p - anchor); }
};

template <class Centre>
Placement placement_for(std::size_t n, Centre&& centre, const VolumeDescription& v) {
  glm::dvec3 lo(1e300), hi(-1e300);
  for (std::size_t i = 0; i < n; ++i) {
    lo = glm::min(lo, centre(i));
    hi = glm::max(hi, centre(i));
  }
  Placement p;
  p.anchor = v.anchor_center ? 0.5 * (lo + hi) : glm::dvec3(0.0);
  p.scale = v.scale;
  if (v.size > 0.0f) {
    const glm::dvec3 extent = hi - lo;
    const double longest = std::max({extent.x, extent.y, extent.z});
    p.scale = longest > 0.0 ? double(v.size) / longest : 1.0;
  }
  p.at = glm::dvec3(v.position);
  return p;
}

void use_albedo(ParticleFile& file, double albedo) {
  const float a = float(albedo);
  for (GaussianParticle& p : file.particles) p.r = p.g = p.b = a;
  for (AnisotropicGaussian& g : file.anisotropic) g.color = glm::vec3(a);
}

}  // namespace

void place_volume_particles(std::vector<GaussianParticle>& particles, const VolumeDescription& v) {
  if (particles.empty()) return;
  const Placement place = placement_for(
      particles.size(), [&](std::size_t i) { return glm::dvec3(particles[i].x, particles[i].y, particles[i].z); }, v);
  for (GaussianParticle& p : particles) {
    const glm::dvec3 q = place.apply(glm::dvec3(p.x, p.y, p.z));
    p.x = float(q.x);
    p.y = float(q.y);
    p.z = float(q.z);
    p.radius = float(place.scale * p.radius);
  }
}

void place_volume_particles(std::vector<AnisotropicGaussian>& particles, const VolumeDescription& v) {
  if (particles.empty()) return;
  const Placement place =
      placement_for(particles.size(), [&](std::size_t i) { return glm::dvec3(particles[i].centre); }, v);
  for (AnisotropicGaussian& g : particles) {
    g.centre = glm::vec3(place.apply(glm::dvec3(g.centre)));
    g.scale = glm::vec3(place.scale * glm::dvec3(g.scale));
    g.extinction = float(double(g.extinction) / place.scale);
  }
}

SceneVolume load_scene_volume(const SceneDescription& scene, const VolumeDescription& v, int threads) {
  const std::string place = v.pointer + (v.used_fallback ? "/fallback" : "/file");
  SceneVolume out;
  try {
    if (v.kind == VolumeFileKind::particles) {
      ParticleFile file = read_particle_file(v.path);
      // Lit media ("shadows"): relit every frame from the medium's albedo, not the colours the
      // import lit.
      if (scene.shadows) use_albedo(file, imported_albedo(v.path, file));
      out.particles = std::move(file.particles);
      out.anisotropic = std::move(file.anisotropic);
    } else {
      const DenseGrid grid = read_vdb_grid(v.path, {v.grid, v.grid_index}, &out.note);
      out.grid = grid.name;
      out.active_voxels = grid.active_voxels;
      CloudImportOptions opt;
      opt.medium.extinction = v.extinction > 0.0f ? double(v.extinction) : default_extinction(grid);
      // Lit as the renderers light the scene (systems/lighting), once, at import; in a scene with
      // lit media ("shadows") the light phase lights them every frame, so the particles keep
      // their albedo (no sun, ambient 1: albedo x (0 T + 1)).
      const SceneLighting lighting = combine_lights(scene.directional_lights, scene.ambient_lights);
      opt.medium.light_direction = glm::dvec3(lighting.sun_direction);
      opt.medium.light_color = scene.shadows ? glm::dvec3(0.0) : glm::dvec3(lighting.sun_color);
      opt.medium.ambient = scene.shadows ? glm::dvec3(1.0) : glm::dvec3(lighting.ambient);
      opt.medium.background = glm::dvec3(scene.background);
      opt.tau_tolerance = tau_tolerance_for_error(v.error);
      opt.threads = threads;
      out.particles = import_cloud(grid, opt);
    }
  } catch (const UserError& e) {
    throw UserError(scene.file, place, std::string("cannot use volume file: ") + e.what());
  }
  place_volume_particles(out.particles, v);
  place_volume_particles(out.anisotropic, v);
  return out;
}

ParticlePool to_particle_pool(const std::vector<GaussianParticle>& particles) {
  ParticlePool pool(particles.size());
  for (const GaussianParticle& p : particles) {
    ParticleInit init;
    init.position = {p.x, p.y, p.z};
    init.radius = p.radius;
    init.density = p.density;
    init.color = {p.r, p.g, p.b};
    pool.spawn(init);
  }
  return pool;
}

}  // namespace pyro
