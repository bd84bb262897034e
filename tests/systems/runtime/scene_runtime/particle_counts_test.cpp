// The particle counts every report uses, on a hand-built world: live and capacity per pool in
// entity order, emitters by name and their live particles per medium, and the draw list's size.
#include <gtest/gtest.h>

#include "components/draw_list.h"
#include "components/emitter.h"
#include "components/particle_medium.h"
#include "components/particle_set.h"
#include "systems/runtime/scene_runtime/particle_counts.h"

namespace pyro {
namespace {

ParticleSet pool_with(size_t capacity, std::vector<ParticleMedium> media) {
  ParticleSet set{ParticlePool(capacity)};
  for (ParticleMedium m : media) {
    const auto i = set.pool.spawn(ParticleInit{});
    set.pool.medium[*i] = static_cast<uint8_t>(m);
  }
  return set;
}

TEST(ParticleCounts, CountsEveryPoolAndTheEmittersMedia) {
  ecs::World world;
  const ecs::Entity cloud = world.create();
  world.emplace<ParticleSet>(cloud, pool_with(10, {ParticleMedium::dust, ParticleMedium::dust}));
  const ecs::Entity fire = world.create();
  Emitter emitter;
  emitter.name = "fire";
  world.emplace<Emitter>(fire, std::move(emitter));
  world.emplace<ParticleSet>(
      fire, pool_with(8, {ParticleMedium::fire, ParticleMedium::smoke, ParticleMedium::fire}));

  const ParticleCensus c = count_particles(world);
  EXPECT_EQ(c.live, 5u);
  EXPECT_EQ(c.capacity, 18u);
  ASSERT_EQ(c.sources.size(), 2u);
  EXPECT_EQ(c.sources[0].name, "particle set 0");
  EXPECT_EQ(c.sources[0].live, 2u);
  EXPECT_EQ(c.sources[1].name, "fire");
  EXPECT_EQ(c.sources[1].capacity, 8u);
  // Only emitters' particles are counted by medium (a cloud's medium field means nothing).
  EXPECT_EQ(c.by_medium, (std::map<std::string, uint64_t>{{"fire", 2}, {"smoke", 1}}));
  EXPECT_EQ(live_particles(world), 5u);

  EXPECT_EQ(drawn_particles(world), 0u);  // no frame drawn yet
  EyeDrawLists lists;
  lists.eyes.resize(2);
  lists.eyes[0].center_radius.resize(4);
  lists.eyes[1].center_radius.resize(3);
  world.set_resource<EyeDrawLists>(std::move(lists));
  EXPECT_EQ(drawn_particles(world), 4u);  // the first view's
}

}  // namespace
}  // namespace pyro
