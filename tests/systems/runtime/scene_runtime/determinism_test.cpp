// Determinism: the particle state after N frames is the same bit for bit whether the
// frames were rendered or only simulated (what `pyro render --frames A:B` does before A), and for
// two runtimes of the same scene; the CPU reference image does not depend on the thread count.
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "components/particle_set.h"
#include "engine/core/rng.h"
#include "systems/runtime/scene/scene_loader.h"
#include "engine/math/camera_math.h"
#include "systems/runtime/reference/particle_reference.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"
#include "tests/support/small_runtime.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

// Every live particle of every pool, every array, as raw bytes (so -0.0 != 0.0 and NaN payloads
// count).
std::string particle_state(SceneRuntime& runtime) {
  std::string bytes;
  runtime.world().each<ParticleSet>([&](ParticleSet& set) {
    ParticlePool& p = set.pool;
    const auto append = [&](const auto& v) {
      bytes.append(reinterpret_cast<const char*>(v.data()), p.size() * sizeof(v[0]));
    };
    bytes += std::to_string(p.size()) + ";";
    for (const auto* v : {&p.px, &p.py, &p.pz, &p.vx, &p.vy, &p.vz, &p.radius, &p.density, &p.r,
                          &p.g, &p.b, &p.age, &p.lifetime, &p.temperature, &p.opacity, &p.size0})
      append(*v);
    append(p.medium);
    append(p.id);
  });
  return bytes;
}

TEST(Determinism, SimulatedFramesLeaveTheStateRenderedFramesLeave) {
  const SceneDescription scene = load_scene(test::scene_path("explosion.json"));
  SceneRuntime rendered(scene, test::small_runtime()), simulated(scene, test::small_runtime()), mixed(scene, test::small_runtime());
  for (int f = 0; f < 40; ++f) {
    rendered.step();
    simulated.simulate_step();
    if (f % 3 == 0) mixed.step(); else mixed.simulate_step();
  }
  EXPECT_EQ(rendered.frame(), 40u);
  EXPECT_EQ(simulated.frame(), 40u);
  const std::string state = particle_state(rendered);
  EXPECT_GT(state.size(), 263u * 60u) << "the explosion's particles are alive";
  EXPECT_TRUE(state == particle_state(simulated));
  EXPECT_TRUE(state == particle_state(mixed));
}

TEST(Determinism, ReferenceImageDoesNotDependOnTheThreadCount) {
  ParticlePool pool(300);
  Rng rng(8);
  for (int i = 0; i < 300; ++i) {
    ParticleInit p;
    p.position = {rng.uniform(-2.0f, 2.0f), rng.uniform(-2.0f, 2.0f), rng.uniform(-2.0f, 2.0f)};
    p.radius = rng.uniform(0.2f, 0.8f);
    p.density = rng.uniform(0.05f, 0.6f);
    p.color = {rng.uniform(0.0f, 1.0f), rng.uniform(0.0f, 1.0f), rng.uniform(0.0f, 1.0f)};
    pool.spawn(p);
  }
  const CameraFrame cam = make_camera_frame({1, 2, 9}, {0, 0, 0}, {0, 1, 0}, 40.0f, 0.1f, 100.0f, 37, 29);
  const RgbImage one = render_particles_reference(pool, cam, glm::dvec3(0.3, 0.4, 0.5), 1);
  for (int threads : {2, 4}) {
    const RgbImage many = render_particles_reference(pool, cam, glm::dvec3(0.3, 0.4, 0.5), threads);
    ASSERT_EQ(many.rgb.size(), one.rgb.size());
    EXPECT_EQ(std::memcmp(many.rgb.data(), one.rgb.data(), one.rgb.size() * sizeof(float)), 0)
        << threads << " threads";
  }
}

}  // namespace
}  // namespace pyro
