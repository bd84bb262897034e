#include "systems/runtime/cloud_import/scene_volume.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include <glm/geometric.hpp>

#include "engine/core/user_error.h"
#include "engine/io/particle_file.h"
#include "engine/io/vdb_reader.h"
#include "engine/io/vdb_temperature_grid.h"
#include "systems/runtime/cloud_import/cloud_import.h"
#include "systems/runtime/cloud_import/fire_exposure.h"
#include "systems/runtime/cloud_import/gaussian_temperature.h"
#include "systems/runtime/cloud_import/grid_gaussian.h"
#include "systems/runtime/cloud_import/volume_fire.h"
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

// Isotropic particles carry their emission in their colours, which a lit scene replaces by the
// albedo: their fire is refused there rather than dropped.
void refuse_lit_isotropic_fire(const SceneDescription& scene, const VolumeDescription& v) {
  throw UserError(scene.file, v.pointer + "/emission",
                  "a volume that emits in a scene with \"shadows\" to be anisotropic particles (a version 2 file "
                  "made by pyro import-vdb); this one is isotropic. Import it with pyro import-vdb, or turn its "
                  "fire off (\"temperature_grid\": \"none\" or \"emission\": {\"intensity\": 0})");
}

// A particle file's fire: its temperature channel, with the map its import recorded.
std::string particle_file_fire(const SceneDescription& scene, const VolumeDescription& v, ParticleFile& file) {
  if (file.temperature.empty()) return "";
  const std::optional<RecordedTemperature> rec = recorded_temperature(v.path, file);
  double hottest = rec ? rec->max : 0.0;
  for (float t : file.temperature) hottest = std::max(hottest, double(t));
  std::optional<TemperatureMapping> recorded;
  if (rec) {
    recorded.emplace();
    recorded->scale = rec->scale;
    recorded->offset = rec->offset;
  }
  const TemperatureEmission e = volume_temperature_emission(
      v.emission, volume_temperature_mapping(v.emission, recorded, hottest), hottest,
      rec ? rec->intensity : kDefaultEmissionIntensity);
  apply_emission(file.anisotropic, file.temperature, e);
  if (add_emission_to_colours(file.particles, file.temperature, e) && scene.shadows) refuse_lit_isotropic_fire(scene, v);
  return describe_volume_emission(rec ? rec->grid : "", v.emission, recorded.has_value(), e);
}

// The temperature grid a VDB volume's fire comes from (none: no fire), named as the scene's
// entry names it.
std::optional<VdbGridInfo> vdb_fire_grid(const SceneDescription& scene, const VolumeDescription& v) {
  try {
    return choose_temperature_grid(v.path, list_vdb_grids(v.path), v.temperature_grid, "");
  } catch (const UserError& e) {
    throw UserError(scene.file, v.pointer + "/temperature_grid", v.path + ": " + e.expected());
  }
}

// The intensity that exposes the particles' fire (fire_exposure.h): their brightest line of
// sight at intensity 1, emitting alone.
double particles_exposure(const DenseGrid& grid, const std::vector<GaussianParticle>& particles,
                          const std::vector<float>& temperatures, const TemperatureMapping& mapping,
                          double hottest_value, int threads) {
  const TemperatureEmission unit = make_temperature_emission(mapping, 1.0, hottest_value);
  std::vector<GaussianParticle> glowing = particles;
  for (size_t i = 0; i < glowing.size(); ++i) {
    const glm::vec3 le = i < temperatures.size() ? emitted_radiance(unit, temperatures[i]) : glm::vec3(0.0f);
    glowing[i].r = le.x;
    glowing[i].g = le.y;
    glowing[i].b = le.z;
  }
  return exposure_for_sightline(brightest_particle_sightline(grid, glowing, 64, threads));
}

// A VDB file's fire, on load: the temperature grid beside the density, each imported particle's
// temperature (gaussian_temperature.h) and its emission added to its colour, exposed
// (fire_exposure.h) unless the scene gives the intensity.
std::string vdb_fire(const SceneDescription& scene, const VolumeDescription& v, const VdbGridInfo& info,
                     const DenseGrid& grid, const CloudImportOptions& opt, std::vector<GaussianParticle>& particles) {
  const DenseGrid heat = read_temperature_grid(v.path, info, grid);
  const std::vector<float> temperatures =
      gaussian_temperatures(grid, heat, grid_gaussians_from_particles(grid, particles, opt.medium), opt.threads);
  const TemperatureMapping mapping = volume_temperature_mapping(v.emission, std::nullopt, heat.max_value);
  const double exposure = v.emission.intensity_given ? 0.0 : particles_exposure(grid, particles, temperatures, mapping, heat.max_value, opt.threads);
  const TemperatureEmission e = volume_temperature_emission(v.emission, mapping, heat.max_value, exposure);
  if (add_emission_to_colours(particles, temperatures, e) && scene.shadows) refuse_lit_isotropic_fire(scene, v);
  return describe_volume_emission(info.name, v.emission, false, e);
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
      out.fire_note = particle_file_fire(scene, v, file);
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
      // The key light (a scene without suns keeps the default direction, its light black).
      opt.medium.light_direction = glm::dvec3(lighting.key() ? lighting.key()->travel : SunLight{}.travel);
      opt.medium.light_color = scene.shadows ? glm::dvec3(0.0) : glm::dvec3(lighting.key_radiance());
      opt.medium.ambient = scene.shadows ? glm::dvec3(1.0) : glm::dvec3(lighting.ambient);
      opt.medium.background = glm::dvec3(scene.background);
      opt.tau_tolerance = tau_tolerance_for_error(v.error);
      opt.threads = threads;
      const std::optional<VdbGridInfo> fire = vdb_fire_grid(scene, v);
      if (fire) opt.medium.albedo = kFireSmokeAlbedo;
      out.particles = import_cloud(grid, opt);
      if (fire) out.fire_note = vdb_fire(scene, v, *fire, grid, opt, out.particles);
    }
  } catch (const UserError& e) {
    if (e.file() == scene.file) throw;  // the entry's own keys: already placed in the scene
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
