#include "systems/runtime/reference/world_snapshot.h"

#include "components/particle_set.h"

namespace pyro {

ParticlePool gather_particles(ecs::World& world) {
  size_t total = 0;
  world.each<ParticleSet>([&](ecs::Entity, ParticleSet& s) { total += s.pool.size(); });
  ParticlePool all(total);
  world.each<ParticleSet>([&](ecs::Entity, ParticleSet& s) {
    const ParticlePool& p = s.pool;
    for (size_t i = 0; i < p.size(); ++i) {
      ParticleInit init;
      init.position = {p.px[i], p.py[i], p.pz[i]};
      init.radius = p.radius[i];
      init.density = p.density[i];
      init.color = {p.r[i], p.g[i], p.b[i]};
      all.spawn(init);
    }
  });
  return all;
}

RgbImage rgb_of(const FrameImage& image) {
  RgbImage out;
  out.width = image.width;
  out.height = image.height;
  out.rgb.resize(static_cast<size_t>(image.width) * image.height * 3);
  for (size_t i = 0, n = out.rgb.size() / 3; i < n; ++i)
    for (size_t c = 0; c < 3; ++c) out.rgb[3 * i + c] = image.rgba[4 * i + c];
  return out;
}

}  // namespace pyro
