// Emitters' medium-dependent defaults (systems/runtime/scene/emitter_defaults.h): a smoke emitter written
// with no dynamics keys rises (its particles' mean height grows over the first seconds), an
// explicitly heavy one still sinks, and dust keeps full gravity.
#include <gtest/gtest.h>

#include <string>

#include "components/emitter.h"
#include "components/frame_clock.h"
#include "components/particle_dynamics.h"
#include "components/particle_set.h"
#include "components/simulation_environment.h"
#include "engine/ecs/world.h"
#include "systems/animation/particle_animation_system.h"
#include "systems/emitter/emitter_system.h"
#include "systems/runtime/scene/scene_loader.h"

namespace pyro {
namespace {

// A scene of one emitter entry (`entry`: the JSON object's keys after the shape and rate).
SceneDescription one_emitter_scene(const std::string& entry) {
  return parse_scene(R"({"emitters": [{"shape": {"type": "point", "position": [0, 2, 0]},
                                       "rate": 20, "lifetime": 10, "seed": 3)" +
                         entry + "}]}",
                     "emitter_defaults.json");
}

// The mean height of the emitter's live particles after each of `seconds` seconds (20 steps a
// second), the environment the scene's defaults.
std::vector<double> mean_heights(const SceneDescription& scene, int seconds) {
  ecs::World world;
  world.set_resource<FrameClock>(FrameClock{0, 0.05f});
  world.set_resource<SimulationEnvironment>(scene.environment);
  const ecs::Entity e = world.create();
  Emitter emitter = scene.emitters.at(0).emitter;
  emitter.rng = Rng(emitter.seed);
  world.emplace<Emitter>(e, emitter);
  world.emplace<ParticleDynamics>(e, scene.emitters.at(0).dynamics);
  world.emplace<ParticleSet>(e, ParticleSet{ParticlePool(emitter.budget)});
  std::vector<double> out;
  for (int step = 1; step <= 20 * seconds; ++step) {
    emitter_system().run(world);
    animation_system().run(world);
    world.resource<FrameClock>().frame += 1;
    if (step % 20 != 0) continue;
    const ParticlePool& p = world.get<const ParticleSet>(e).pool;
    double sum = 0.0;
    for (size_t i = 0; i < p.size(); ++i) sum += p.py[i];
    out.push_back(p.size() ? sum / double(p.size()) : 0.0);
  }
  return out;
}

TEST(EmitterDefaults, SmokeWithNoDynamicsKeysRises) {
  const SceneDescription scene = one_emitter_scene("");
  ASSERT_EQ(scene.emitters.at(0).emitter.medium, ParticleMedium::smoke);  // the default medium
  const std::vector<double> y = mean_heights(scene, 3);
  std::printf("smoke, defaults: mean height after 1, 2, 3 s: %.3f %.3f %.3f (born at 2)\n", y[0], y[1], y[2]);
  EXPECT_GT(y[0], 2.0);
  EXPECT_GT(y[1], y[0]);
  EXPECT_GT(y[2], y[1]);
}

TEST(EmitterDefaults, FireWithNoDynamicsKeysRises) {
  const std::vector<double> y = mean_heights(one_emitter_scene(R"(, "medium": "fire")"), 2);
  EXPECT_GT(y[0], 2.0);
  EXPECT_GT(y[1], y[0]);
}

TEST(EmitterDefaults, ExplicitlyHeavySmokeStillSinks) {
  const std::vector<double> y = mean_heights(
      one_emitter_scene(R"(, "dynamics": {"gravity_scale": 1, "buoyancy": 0, "drag": 0, "collide": false})"), 2);
  EXPECT_LT(y[0], 2.0);
  EXPECT_LT(y[1], y[0]);
}

TEST(EmitterDefaults, DustKeepsFullGravityAndKeysWin) {
  const SceneDescription dust = one_emitter_scene(R"(, "medium": "dust")");
  EXPECT_EQ(dust.emitters[0].dynamics.gravity_scale, 1.0f);
  EXPECT_EQ(dust.emitters[0].dynamics.buoyancy, 0.0f);
  const SceneDescription smoke = one_emitter_scene(R"(, "temperature": 600, "dynamics": {"buoyancy": 0.02})");
  EXPECT_EQ(smoke.emitters[0].dynamics.buoyancy, 0.02f);
  EXPECT_EQ(smoke.emitters[0].dynamics.gravity_scale, 0.0f);
  EXPECT_EQ(smoke.emitters[0].emitter.temperature.value, 600.0f);
}

}  // namespace
}  // namespace pyro
