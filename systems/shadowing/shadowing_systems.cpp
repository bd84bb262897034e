#include "systems/shadowing/shadowing_systems.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

#include <glm/geometric.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "components/anisotropic_cloud.h"
#include "components/mesh_instance.h"
#include "components/mesh_shadow.h"
#include "components/particle_light.h"
#include "components/particle_set.h"
#include "components/render_settings.h"
#include "components/scene_lighting.h"
#include "components/shadow_settings.h"
#include "components/shadow_volume.h"
#include "engine/math/shadow_ray_index.h"
#include "systems/shadowing/mesh_shadow_map.h"
#include "systems/shadowing/opacity_shadow_map.h"

namespace pyro {

namespace {

constexpr std::size_t kParticlesPerTask = 1024;

// The world's lit particle sets in entity-index order.
std::vector<std::pair<uint32_t, std::pair<const ParticlePool*, ParticleLight*>>> lit_sets(ecs::World& world) {
  std::vector<std::pair<uint32_t, std::pair<const ParticlePool*, ParticleLight*>>> sets;
  world.each<const ParticleSet, ParticleLight>([&](ecs::Entity e, const ParticleSet& s, ParticleLight& l) {
    sets.push_back({e.index, {&s.pool, &l}});
  });
  std::sort(sets.begin(), sets.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  return sets;
}

bool sunlit(const SceneLighting& lighting) { return lighting.key_shines(); }

bool sphere_casters(ecs::World& world) {
  const RenderSettings* settings = world.try_resource<const RenderSettings>();
  return settings && settings->media_layers();
}

// Particle i of `p` as the light phase sees it.
ShadowCaster caster_of(const ParticlePool& p, std::size_t i, bool spheres) {
  const glm::dvec3 c(p.px[i], p.py[i], p.pz[i]);
  const float density = std::max(p.density[i], 0.0f);
  if (spheres) return ConeSphere{c, p.radius[i], double(density) * p.opacity[i]};
  return clamped_gaussian(c, p.radius[i], density);
}

// The world's lit anisotropic clouds in entity-index order.
std::vector<std::pair<uint32_t, std::pair<const AnisotropicCloud*, ParticleLight*>>> lit_clouds(ecs::World& world) {
  std::vector<std::pair<uint32_t, std::pair<const AnisotropicCloud*, ParticleLight*>>> clouds;
  world.each<const AnisotropicCloud, ParticleLight>(
      [&](ecs::Entity e, const AnisotropicCloud& c, ParticleLight& l) { clouds.push_back({e.index, {&c, &l}}); });
  std::sort(clouds.begin(), clouds.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  return clouds;
}

}  // namespace

std::vector<ShadowCaster> shadow_casters(ecs::World& world) {
  const bool spheres = sphere_casters(world);
  // The lit sets in entity-index order, read only.
  std::vector<std::pair<uint32_t, const ParticlePool*>> sets;
  world.each<const ParticleSet, const ParticleLight>(
      [&](ecs::Entity e, const ParticleSet& s, const ParticleLight&) { sets.push_back({e.index, &s.pool}); });
  std::sort(sets.begin(), sets.end());
  std::vector<ShadowCaster> casters;
  for (const auto& [index, pool] : sets) {
    const ParticlePool& p = *pool;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.density[i] > 0.0f) casters.push_back(caster_of(p, i, spheres));
  }
  // Then the anisotropic clouds', in entity-index order.
  std::vector<std::pair<uint32_t, const AnisotropicCloud*>> clouds;
  world.each<const AnisotropicCloud, const ParticleLight>(
      [&](ecs::Entity e, const AnisotropicCloud& c, const ParticleLight&) { clouds.push_back({e.index, &c}); });
  std::sort(clouds.begin(), clouds.end());
  for (const auto& [index, cloud] : clouds) append_casters(cloud->particles, casters);
  return casters;
}

namespace {

// A particle's light from `depth(p)`, the optical depth toward the sun at p of every particle:
// that of the others at its centre and its gradient (central differences `h` apart, about a
// standard deviation), its own closed form (`self`) taken out.
template <class Depth>
glm::vec4 particle_light(const ShadowCaster& self, double h, const glm::dvec3& toward_sun, Depth&& depth) {
  const glm::dvec3 c = self.c;
  const auto others = [&](const glm::dvec3& x) {
    return depth(x) - caster_optical_depth(self, x, toward_sun, 0.0, std::numeric_limits<double>::infinity());
  };
  glm::vec4 o(float(others(c)), 0.0f, 0.0f, 0.0f);
  h = std::max(h, 1e-6);
  for (int a = 0; a < 3; ++a) {
    glm::dvec3 e(0.0);
    e[a] = h;
    o[a + 1] = float((others(c + e) - others(c - e)) / (2.0 * h));
  }
  return o;
}

// An anisotropic particle's standard deviation for the gradient: the geometric mean of its scales.
double mean_scale(const AnisotropicGaussian& g) {
  return std::cbrt(double(g.scale.x) * double(g.scale.y) * double(g.scale.z));
}

// The meshes' shadow as an optical depth (mesh_shadow_depth); 0 without mesh shadows.
double mesh_optical_depth(const MeshShadow* meshes, const glm::dvec3& p) {
  return meshes && !meshes->empty() ? mesh_shadow_depth(*meshes, glm::vec3(p)) : 0.0;
}

// Lights every particle from the media's optical depth `depth` (see particle_light) and the
// meshes' shadow at its centre, set by set in entity-index order, then the anisotropic clouds.
// The meshes' depth is a step at a shadow's edge: it joins the particle's depth, not its
// gradient, so a particle is in the shadow by how much of the light its centre loses (a
// gradient across the step would cut the splat with a hard line).
template <class Depth>
void write_particle_light(ecs::World& world, const glm::vec3& key_travel, Depth&& depth) {
  const glm::dvec3 toward_sun = -glm::normalize(glm::dvec3(key_travel));
  const MeshShadow* meshes = world.try_resource<const MeshShadow>();
  const auto lit = [&](const ShadowCaster& c, double h) {
    glm::vec4 light = particle_light(c, h, toward_sun, depth);
    light.x += float(mesh_optical_depth(meshes, c.c));
    return light;
  };
  const bool spheres = sphere_casters(world);
  const auto each_particle = [](std::size_t n, auto&& light) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, kParticlesPerTask),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        for (std::size_t i = r.begin(); i < r.end(); ++i) light(i);
                      });
  };
  for (const auto& [index, set] : lit_sets(world)) {
    const ParticlePool& p = *set.first;
    ParticleLight& light = *set.second;
    light.others_depth.resize(p.size());
    each_particle(p.size(), [&](std::size_t i) {
      light.others_depth[i] = lit(caster_of(p, i, spheres), double(p.radius[i]) / 3.0);
    });
  }
  for (const auto& [index, cloud] : lit_clouds(world)) {
    const std::vector<AnisotropicGaussian>& gs = cloud.first->particles;
    ParticleLight& light = *cloud.second;
    light.others_depth.resize(gs.size());
    each_particle(gs.size(), [&](std::size_t i) {
      light.others_depth[i] = lit(ShadowCaster(gs[i]), mean_scale(gs[i]));
    });
  }
}

// Lit without shadows: no other particle stands between any particle and the sun.
void write_unshadowed_light(ecs::World& world) {
  for (const auto& [index, set] : lit_sets(world)) set.second->others_depth.assign(set.first->size(), glm::vec4(0.0f));
  for (const auto& [index, cloud] : lit_clouds(world))
    cloud.second->others_depth.assign(cloud.first->particles.size(), glm::vec4(0.0f));
}

const SceneLighting& lighting_of(ecs::World& world) {
  static const SceneLighting defaults;
  const SceneLighting* lit = world.try_resource<const SceneLighting>();
  return lit ? *lit : defaults;
}

void run_shadow_map(ecs::World& world) {
  const ShadowSettings* settings = world.try_resource<const ShadowSettings>();
  if (!settings) return;
  const SceneLighting& lighting = lighting_of(world);
  ShadowVolume& volume = world.resource<ShadowVolume>();
  const bool particles_use_it = settings->method == ShadowMethod::shadow_map;
  const bool receivers = world.size<MeshInstance>() > 0;
  const bool wanted = sunlit(lighting) && settings->method != ShadowMethod::none && (particles_use_it || receivers);
  if (wanted) {
    build_opacity_shadow_map(shadow_casters(world), glm::dvec3(lighting.key()->travel),
                             {settings->map_size, settings->map_slices}, volume);
  } else if (!volume.empty()) {
    const uint64_t version = volume.version + 1;
    volume = ShadowVolume{};
    volume.version = version;
  }
  if (settings->method == ShadowMethod::rays) return;
  if (!particles_use_it || !wanted) {
    write_unshadowed_light(world);
    return;
  }
  write_particle_light(world, lighting.key()->travel,
                       [&](const glm::dvec3& p) { return double(sample_optical_depth(volume, glm::vec3(p))); });
}

void run_shadow_rays(ecs::World& world) {
  const ShadowSettings* settings = world.try_resource<const ShadowSettings>();
  if (!settings || settings->method != ShadowMethod::rays) return;
  const SceneLighting& lighting = lighting_of(world);
  if (!sunlit(lighting)) {
    write_unshadowed_light(world);
    return;
  }
  const ShadowRayIndex index(shadow_casters(world), glm::dvec3(lighting.key()->travel));
  write_particle_light(world, lighting.key()->travel,
                       [&](const glm::dvec3& p) { return index.optical_depth_to_light(p); });
}

}  // namespace

ecs::SystemDesc shadow_map_system() {
  return {.name = "shadow_map",
          .phase = ecs::Phase::light,
          .access = ecs::Access::of<ecs::Reads<ShadowSettings, SceneLighting, RenderSettings, ParticleSet, AnisotropicCloud,
                                               MeshInstance, MeshShadow>,
                                    ecs::Writes<ShadowVolume, ParticleLight>>(),
          .run = run_shadow_map,
          .setup =
              [](ecs::World& world) {
                if (!world.has_resource<ShadowVolume>()) world.set_resource<ShadowVolume>();
              },
          .after = {"lighting", "mesh_shadow"}};
}

ecs::SystemDesc shadow_ray_system() {
  return {.name = "shadow_rays",
          .phase = ecs::Phase::light,
          .access = ecs::Access::of<ecs::Reads<ShadowSettings, SceneLighting, RenderSettings, ParticleSet, AnisotropicCloud,
                                               MeshShadow>,
                                    ecs::Writes<ParticleLight>>(),
          .run = run_shadow_rays,
          .after = {"shadow_map"}};
}

}  // namespace pyro
