#include "systems/cloud_import/scene_volume.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <glm/geometric.hpp>

#include "engine/core/user_error.h"
#include "engine/io/particle_file.h"
#include "engine/io/vdb_reader.h"
#include "systems/cloud_import/cloud_import.h"

namespace pyro {

void place_volume_particles(std::vector<GaussianParticle>& particles, const VolumeDescription& v) {
  if (particles.empty()) return;
  glm::dvec3 lo(1e300), hi(-1e300);
  for (const GaussianParticle& p : particles) {
    lo = glm::min(lo, glm::dvec3(p.x, p.y, p.z));
    hi = glm::max(hi, glm::dvec3(p.x, p.y, p.z));
  }
  const glm::dvec3 anchor = v.anchor_center ? 0.5 * (lo + hi) : glm::dvec3(0.0);
  double s = v.scale;
  if (v.size > 0.0f) {
    const glm::dvec3 extent = hi - lo;
    const double longest = std::max({extent.x, extent.y, extent.z});
    s = longest > 0.0 ? double(v.size) / longest : 1.0;
  }
  const glm::dvec3 at(v.position);
  for (GaussianParticle& p : particles) {
    const glm::dvec3 q = at + s * (glm::dvec3(p.x, p.y, p.z) - anchor);
    p.x = float(q.x);
    p.y = float(q.y);
    p.z = float(q.z);
    p.radius = float(s * p.radius);
  }
}

SceneVolume load_scene_volume(const SceneDescription& scene, const VolumeDescription& v, int threads) {
  const std::string place = v.pointer + (v.used_fallback ? "/fallback" : "/file");
  SceneVolume out;
  try {
    if (v.kind == VolumeFileKind::particles) {
      ParticleFile file = read_particle_file(v.path);
      if (!file.anisotropic.empty())
        throw UserError(v.path, "", "a version 1 particle file (isotropic Gaussian particles), "
                                    "found anisotropic particles (version 2)");
      out.particles = std::move(file.particles);
    } else {
      const DenseGrid grid = read_vdb_grid(v.path, {v.grid, v.grid_index}, &out.note);
      out.grid = grid.name;
      out.active_voxels = grid.active_voxels;
      CloudImportOptions opt;
      opt.medium.extinction = v.extinction > 0.0f ? double(v.extinction) : default_extinction(grid);
      opt.medium.light_direction = glm::dvec3(scene.light.direction);
      opt.medium.light_color = glm::dvec3(scene.light.color);
      opt.medium.ambient = glm::dvec3(scene.light.ambient);
      opt.medium.background = glm::dvec3(scene.background);
      opt.tau_tolerance = tau_tolerance_for_error(v.error);
      opt.threads = threads;
      out.particles = import_cloud(grid, opt);
    }
  } catch (const UserError& e) {
    throw UserError(scene.file, place, std::string("cannot use volume file: ") + e.what());
  }
  place_volume_particles(out.particles, v);
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
