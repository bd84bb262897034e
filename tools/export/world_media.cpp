#include "tools/export/world_media.h"

#include <algorithm>
#include <utility>

#include "components/anisotropic_cloud.h"
#include "components/particle_kind.h"
#include "components/particle_medium.h"
#include "components/particle_set.h"
#include "components/render_settings.h"

namespace pyro {

namespace {

bool drawn_as_spheres(ecs::World& world, ecs::Entity e, ParticleShape scene_wide) {
  const ParticleKind* kind = world.try_get<const ParticleKind>(e);
  const ParticleShape shape = kind ? kind->shape : scene_wide;
  return shape != ParticleShape::gaussian;
}

MediaSample pool_sample(const ParticlePool& p, std::size_t i, bool spheres) {
  MediaSample s;
  const glm::dvec3 c(p.px[i], p.py[i], p.pz[i]);
  if (spheres)
    s.field = ConeSphere{c, p.radius[i], double(p.density[i]) * std::max(p.opacity[i], 0.0f)};
  else
    s.field = clamped_gaussian(c, p.radius[i], p.density[i]);
  s.color = {p.r[i], p.g[i], p.b[i]};
  s.temperature = p.temperature[i];
  s.fire = p.medium[i] == uint8_t(ParticleMedium::fire);
  s.medium = ParticleMedium(p.medium[i]);
  s.detail = p.radius[i] / 3.0;
  return s;
}

void append_clouds(ecs::World& world, std::vector<MediaSample>& out) {
  std::vector<std::pair<uint32_t, const AnisotropicCloud*>> clouds;
  world.each<const AnisotropicCloud>([&](ecs::Entity e, const AnisotropicCloud& c) { clouds.push_back({e.index, &c}); });
  std::sort(clouds.begin(), clouds.end());
  for (const auto& [index, cloud] : clouds)
    for (const AnisotropicGaussian& g : cloud->particles) {
      if (!(g.extinction > 0.0f)) continue;
      MediaSample s;
      s.field = ShadowCaster(g);
      s.color = g.color;
      s.emission = g.emission;
      s.detail = std::min({g.scale.x, g.scale.y, g.scale.z});
      out.push_back(s);
    }
}

}  // namespace

std::vector<MediaSample> world_media(ecs::World& world) {
  const RenderSettings* settings = world.try_resource<const RenderSettings>();
  const ParticleShape scene_wide = settings ? settings->particles : ParticleShape::gaussian;
  std::vector<std::pair<uint32_t, std::pair<const ParticlePool*, bool>>> sets;
  world.each<const ParticleSet>([&](ecs::Entity e, const ParticleSet& s) {
    sets.push_back({e.index, {&s.pool, drawn_as_spheres(world, e, scene_wide)}});
  });
  std::sort(sets.begin(), sets.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<MediaSample> out;
  for (const auto& [index, set] : sets) {
    const auto& [pool, spheres] = set;
    for (std::size_t i = 0; i < pool->size(); ++i)
      if (pool->density[i] > 0.0f && pool->radius[i] > 0.0f) out.push_back(pool_sample(*pool, i, spheres));
  }
  append_clouds(world, out);
  return out;
}

}  // namespace pyro
