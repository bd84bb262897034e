// The scene file's "environment" and "emitters": every key read into the components,
// refusals with JSON pointers and suggestions, and a scene that runs its emitters.
#include <gtest/gtest.h>

#include "components/emitter.h"
#include "components/particle_set.h"
#include "engine/core/user_error.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"

namespace pyro {
namespace {

const std::string kFile = "emitters.json";

const char* kScene = R"({
  "seed": 5,
  "output": {"width": 64, "height": 48, "fps": 20},
  "environment": {"gravity": [0, -9.81, 0], "wind": [1, 0, 0], "ambient_temperature": 300,
                  "ground": {"height": 0}, "spheres": [{"center": [0, 1, 0], "radius": 0.5}],
                  "boxes": [{"min": [2, 0, -1], "max": [3, 1, 1]}], "particle_budget": 500,
                  "prewarm": 0.5},
  "emitters": [
    {"name": "fire", "medium": "fire",
     "shape": {"type": "sphere", "position": [0, 1, 0], "radius": 0.4, "surface": false},
     "rate": 60, "start": 0, "duration": 2, "bursts": [{"time": 0.2, "count": 5}, {"time": 0, "count": 30}],
     "direction": [0, 1, 0], "cone_deg": 25, "radial": true,
     "speed": {"min": 1, "max": 3}, "size": 0.3,
     "lifetime": {"mean": 1.5, "stddev": 0.3, "min": 0.5, "max": 3},
     "density": 0.4, "temperature": {"mean": 2800, "stddev": 150},
     "color": [1, 0.6, 0.2], "budget": 200, "seed": 3,
     "dynamics": {"gravity_scale": 0.2, "buoyancy": 0.004, "drag": 1.5, "turbulence": 0.8,
                  "turbulence_frequency": 0.7, "turbulence_speed": 0.2, "turbulence_seed": 4,
                  "cooling": 0.9, "smoke_below": 1300, "collide": true, "restitution": 0.2,
                  "friction": 0.4,
                  "curves": {"size": [[0, 1], [1, 2.5]], "opacity": [[0, 0], [0.1, 1], [1, 0]],
                             "temperature": [[0, 3000], [1, 800]],
                             "color": [[0, [1, 0.5, 0.1]], [1, [0.2, 0.2, 0.2]]]}}},
    {"medium": "dust", "shape": {"type": "disc", "radius": 2, "axis": [0, 1, 0]},
     "bursts": [{"time": 0, "count": 16}], "budget": 16}
  ]
})";

TEST(SceneEmitters, EveryKeyIsRead) {
  const SceneDescription s = parse_scene(kScene, kFile);
  EXPECT_EQ(s.environment.wind.x, 1.0f);
  EXPECT_TRUE(s.environment.ground);
  ASSERT_EQ(s.environment.spheres.size(), 1u);
  ASSERT_EQ(s.environment.boxes.size(), 1u);
  EXPECT_EQ(s.environment.particle_budget, 500u);
  EXPECT_EQ(s.prewarm, 0.5f);
  ASSERT_EQ(s.emitters.size(), 2u);
  const Emitter& e = s.emitters[0].emitter;
  EXPECT_EQ(e.medium, ParticleMedium::fire);
  EXPECT_EQ(e.shape, EmitterShape::sphere);
  ASSERT_EQ(e.bursts.size(), 2u);
  EXPECT_EQ(e.bursts[0].count, 30u);  // sorted by time
  EXPECT_EQ(e.speed.kind, DistributionKind::uniform);
  EXPECT_EQ(e.lifetime.kind, DistributionKind::normal);
  EXPECT_EQ(e.temperature.min, 2800.0f - 450.0f);  // default clamp: mean ± 3 stddev
  EXPECT_EQ(e.size.kind, DistributionKind::constant);
  EXPECT_EQ(e.budget, 200u);
  const ParticleDynamics& d = s.emitters[0].dynamics;
  EXPECT_EQ(d.smoke_below, 1300.0f);
  ASSERT_EQ(d.color.keys.size(), 2u);
  EXPECT_EQ(d.color.keys[1].value.x, 0.2f);
  EXPECT_EQ(s.emitters[1].emitter.shape, EmitterShape::disc);
}

void expect_error(const std::string& text, const std::string& place, const std::string& fragment) {
  try {
    parse_scene(text, kFile);
    ADD_FAILURE() << "no error for " << text;
  } catch (const UserError& e) {
    EXPECT_EQ(e.place(), place) << e.what();
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(SceneEmitters, MistakesAreNamedByPointer) {
  expect_error(R"({"emitters": [{"rat": 3}]})", "/emitters/0/rat", "did you mean \"rate\"");
  expect_error(R"({"emitters": [{"medium": "fir"}]})", "/emitters/0/medium", "did you mean \"fire\"");
  expect_error(R"({"emitters": [{"shape": {"type": "cube"}}]})", "/emitters/0/shape/type", "expected one of");
  expect_error(R"({"emitters": [{"speed": {"min": 3, "max": 1}}]})", "/emitters/0/speed", "min <= max");
  expect_error(R"({"emitters": [{"speed": {"mean": 3}}]})", "/emitters/0/speed", "\"stddev\"");
  expect_error(R"({"emitters": [{"size": 0}]})", "/emitters/0/size", "expected a number in (0");
  expect_error(R"({"emitters": [{"bursts": [{"time": 1}]}]})", "/emitters/0/bursts/0", "\"count\"");
  expect_error(R"({"emitters": [{"dynamics": {"curves": {"size": [[0.5, 1], [0.2, 2]]}}}]})",
               "/emitters/0/dynamics/curves/size/1/0", "greater than the previous");
  expect_error(R"({"emitters": [{"radial": 1}]})", "/emitters/0/radial", "true or false");
  expect_error(R"({"environment": {"prewarm": -1}})", "/environment/prewarm", "expected a number");
  expect_error(R"({"environment": {"boxes": [{"min": [0, 0, 0], "max": [1, 0, 1]}]}})",
               "/environment/boxes/0/max", "min");
}

TEST(SceneEmitters, RuntimeSpawnsAnimatesAndPrewarms) {
  const SceneDescription s = parse_scene(kScene, kFile);
  RuntimeOptions o;
  o.readback = false;
  SceneRuntime rt(s, o);
  // Prewarm 0.5 s at 20 fps = 10 steps ran in the constructor: bursts and 9 steps of rate.
  std::size_t fire = 0, dust = 0;
  rt.world().each<Emitter, ParticleSet>([&](Emitter& e, ParticleSet& p) {
    (e.medium == ParticleMedium::fire ? fire : dust) = p.pool.size();
  });
  EXPECT_GT(fire, 30u);
  EXPECT_EQ(dust, 16u);
  for (int f = 0; f < 5; ++f) rt.step();
  const auto order = rt.schedule().order();
  EXPECT_NE(std::find(order.begin(), order.end(), "emitter"), order.end());
  EXPECT_NE(std::find(order.begin(), order.end(), "animation"), order.end());
  // Same scene, same particles.
  SceneRuntime again(s, o);
  for (int f = 0; f < 5; ++f) again.step();
  std::vector<float> a, b;
  rt.world().each<Emitter, ParticleSet>([&](Emitter&, ParticleSet& p) { a.insert(a.end(), p.pool.px.begin(), p.pool.px.begin() + p.pool.size()); });
  again.world().each<Emitter, ParticleSet>([&](Emitter&, ParticleSet& p) { b.insert(b.end(), p.pool.px.begin(), p.pool.px.begin() + p.pool.size()); });
  EXPECT_EQ(a, b);
  EXPECT_FALSE(a.empty());
}

}  // namespace
}  // namespace pyro
