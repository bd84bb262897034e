// Scene budgets: the `budget` object is validated, the cost is counted from the scene, and a
// scene over any limit is refused with its numbers and the place of the limit.
#include <gtest/gtest.h>

#include "engine/particles/particle_pool.h"

#include <string>

#include "engine/core/user_error.h"
#include "systems/runtime/scene/scene_budget.h"
#include "systems/runtime/scene/scene_loader.h"

namespace pyro {
namespace {

std::string refusal_scene_budget(const SceneDescription& s, const SceneCost& cost, int driver_max) {
  try {
    check_scene_budget(s, cost, driver_max);
  } catch (const UserError& e) {
    return e.place() + " | " + e.what();
  }
  return "";
}

TEST(SceneBudget, DefaultsFitTheBuildMachine) {
  const SceneDescription s = parse_scene("{}", "empty.json");
  EXPECT_EQ(s.budget.particles, 20'000'000u);
  EXPECT_EQ(s.budget.memory_bytes, 4ull << 30);
  EXPECT_EQ(s.budget.texture_size, 0);
}

TEST(SceneBudget, ReadFromTheScene) {
  const SceneDescription s = parse_scene(
      R"({"budget": {"particles": 5000, "memory_mib": 64, "texture_size": 1024}})", "b.json");
  EXPECT_EQ(s.budget.particles, 5000u);
  EXPECT_EQ(s.budget.memory_bytes, 64ull * 1024 * 1024);
  EXPECT_EQ(s.budget.texture_size, 1024);
}

TEST(SceneBudget, BadValuesNameTheirPlace) {
  const char* cases[][2] = {{R"({"budget": {"particles": 1e12}})", "/budget/particles"},
                            {R"({"budget": {"particles": "many"}})", "/budget/particles"},
                            {R"({"budget": {"memory_mib": 0}})", "/budget/memory_mib"},
                            {R"({"budget": {"texture_size": -1}})", "/budget/texture_size"},
                            {R"({"budget": {"textures": 1}})", "/budget"},
                            {R"({"budget": 3})", "/budget"}};
  for (const auto& c : cases) {
    try {
      parse_scene(c[0], "b.json");
      ADD_FAILURE() << "accepted " << c[0];
    } catch (const UserError& e) {
      EXPECT_EQ(e.file(), "b.json");
      EXPECT_EQ(e.place().rfind(c[1], 0), 0u) << c[0] << " -> " << e.what();
    }
  }
}

TEST(SceneBudget, CostCountsCloudsEmittersAndVolumes) {
  const SceneDescription s = parse_scene(
      R"({"clouds": [{"count": 1000}, {"count": 234}],
          "emitters": [{"budget": 50, "bursts": [{"time": 0, "count": 5}]}]})",
      "c.json");
  const SceneCost mono = estimate_scene_cost(s, 100, 50, 1, 100, 7);
  EXPECT_EQ(mono.particles, 1000u + 234u + 50u + 7u);
  EXPECT_EQ(mono.texture_size, 100);
  // The estimate is the particles' storage plus the targets, each linear in its count.
  const SceneCost bigger = estimate_scene_cost(s, 200, 50, 1, 200, 7);
  EXPECT_EQ(bigger.memory_bytes - mono.memory_bytes, 100u * 50u * kTargetBytesPerPixelPerView);
  const SceneCost more = estimate_scene_cost(s, 100, 50, 1, 100, 8);
  EXPECT_EQ(more.memory_bytes - mono.memory_bytes, particle_bytes_estimate(1));
  // The pool alone holds 16 floats, a medium byte and a 32-bit id per particle.
  EXPECT_EQ(ParticlePool::bytes_per_slot(), 16u * 4u + 1u + 4u);
  EXPECT_GE(particle_bytes_estimate(1), ParticlePool::bytes_per_slot());
  EXPECT_GT(particle_bytes_estimate(2), particle_bytes_estimate(1));
  // Billboards other than splats keep the particles gathered per view: more bytes.
  EXPECT_GT(particle_bytes_estimate(1, ParticleShape::spherical), particle_bytes_estimate(1));
  EXPECT_GT(estimate_scene_cost(s, 100, 50, 2, 200, 7).memory_bytes, mono.memory_bytes);
}

TEST(SceneBudget, RefusedWithTheNumbers) {
  SceneDescription s = parse_scene(R"({"clouds": [{"count": 1000}]})", "r.json");
  const SceneCost cost = estimate_scene_cost(s, 640, 480, 1, 640, 0);
  EXPECT_EQ(refusal_scene_budget(s, cost, 16384), "");

  s.budget.particles = 999;
  std::string r = refusal_scene_budget(s, cost, 16384);
  EXPECT_EQ(r.rfind("/budget/particles", 0), 0u) << r;
  EXPECT_NE(r.find("1000"), std::string::npos) << r;
  EXPECT_NE(r.find("999"), std::string::npos) << r;
  EXPECT_NE(r.find("r.json"), std::string::npos) << r;

  s.budget.particles = 1000;
  s.budget.memory_bytes = cost.memory_bytes - 1;
  r = refusal_scene_budget(s, cost, 16384);
  EXPECT_EQ(r.rfind("/budget/memory_mib", 0), 0u) << r;
  EXPECT_NE(r.find("MiB"), std::string::npos) << r;
  s.budget.memory_bytes = cost.memory_bytes;
  EXPECT_EQ(refusal_scene_budget(s, cost, 16384), "");

  s.budget.texture_size = 639;
  r = refusal_scene_budget(s, cost, 16384);
  EXPECT_EQ(r.rfind("/budget/texture_size", 0), 0u) << r;
  EXPECT_NE(r.find("640"), std::string::npos) << r;
  s.budget.texture_size = 0;  // the driver's limit
  r = refusal_scene_budget(s, cost, 512);
  EXPECT_NE(r.find("driver"), std::string::npos) << r;
  EXPECT_NE(r.find("512"), std::string::npos) << r;
}

}  // namespace
}  // namespace pyro
