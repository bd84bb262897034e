// The parallel schedule gives the sequential run's results bit for bit: particle state and
// rendered bytes after N frames of the explosion, the clouds and the VDB cloud at 1, 2 and 4
// threads (TBB allowed that many, the schedule set to that many), and the particle loops that
// split across threads (animation, sorting) on sets large enough to be split.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "components/draw_list.h"
#include "components/frame_image.h"
#include "components/particle_dynamics.h"
#include "components/particle_set.h"
#include "components/simulation_environment.h"
#include "components/view.h"
#include "engine/ecs/world.h"
#include "systems/animation/particle_animation_system.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"
#include "systems/sorting/depth_sort.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

template <class V>
void append(std::string& bytes, const V& v, std::size_t n) {
  bytes.append(reinterpret_cast<const char*>(v.data()), n * sizeof(v[0]));
}

std::string pool_bytes(const ParticlePool& p) {
  std::string bytes = std::to_string(p.size()) + ";";
  for (const auto* v : {&p.px, &p.py, &p.pz, &p.vx, &p.vy, &p.vz, &p.radius, &p.density, &p.r, &p.g,
                        &p.b, &p.age, &p.lifetime, &p.temperature, &p.opacity, &p.size0})
    append(bytes, *v, p.size());
  append(bytes, p.medium, p.size());
  append(bytes, p.id, p.size());
  return bytes;
}

struct RunResult {
  std::string particles;        // every pool, every array, raw bytes
  std::vector<uint8_t> output;  // the composed sRGB frame
  std::vector<float> linear;    // the linear readback of the first view
  std::vector<std::string> threads_used;
};

RunResult run_scene(const std::string& scene, int threads, int frames) {
  const tbb::global_control allow(tbb::global_control::max_allowed_parallelism, threads);
  RuntimeOptions options;
  options.width_override = 64;
  options.height_override = 64;
  options.stereo_mode = StereoMode::side_by_side;
  options.threads = threads;
  SceneRuntime runtime(load_scene(test::scene_path(scene)), options);
  RunResult r;
  for (int f = 0; f < frames; ++f) runtime.step();
  runtime.world().each<ParticleSet>(
      [&](const ParticleSet& s) { r.particles += pool_bytes(s.pool); });
  r.output = runtime.read_output().rgba;
  r.linear = runtime.image().rgba;
  for (const ecs::SystemStats& st : runtime.schedule().stats())
    if (st.thread != 0) r.threads_used.push_back(st.name);
  return r;
}

class ParallelDeterminism : public ::testing::TestWithParam<std::string> {};

TEST_P(ParallelDeterminism, OneTwoAndFourThreadsGiveTheSameBits) {
  const int frames = 12;
  const RunResult one = run_scene(GetParam(), 1, frames);
  EXPECT_TRUE(one.threads_used.empty());  // the sequential schedule stays on the caller
  ASSERT_FALSE(one.particles.empty());
  for (const int threads : {2, 4}) {
    const RunResult many = run_scene(GetParam(), threads, frames);
    EXPECT_TRUE(many.particles == one.particles) << threads << " threads";
    EXPECT_TRUE(many.output == one.output) << threads << " threads";
    ASSERT_EQ(many.linear.size(), one.linear.size());
    EXPECT_EQ(std::memcmp(many.linear.data(), one.linear.data(), one.linear.size() * sizeof(float)),
              0)
        << threads << " threads";
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, ParallelDeterminism,
                         ::testing::Values("explosion.json", "clouds.json", "cloud_vdb.json"),
                         [](const auto& info) {
                           return info.param.substr(0, info.param.find('.'));
                         });

// A pool large enough that animate_particles splits it (its task size is 512 particles).
ParticlePool turbulent_pool(std::size_t n) {
  ParticlePool pool(n);
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(-2.0f, 2.0f);
  for (std::size_t i = 0; i < n; ++i) {
    ParticleInit p;
    p.position = {u(rng), u(rng) + 2.0f, u(rng)};
    p.velocity = {u(rng), u(rng), u(rng)};
    p.temperature = 1500.0f + 400.0f * u(rng);
    p.lifetime = 0.5f + 0.2f * (u(rng) + 2.0f);
    pool.spawn(p);
  }
  return pool;
}

TEST(ParallelDeterminism, SplitParticleLoopsGiveTheSameBits) {
  ParticleDynamics d;
  d.drag = 1.5f;
  d.buoyancy = 0.02f;
  d.turbulence = 2.0f;
  d.collide = true;
  SimulationEnvironment env;
  env.ground = true;
  std::string expected_particles;
  std::vector<glm::vec4> expected_order;
  for (const int threads : {1, 2, 4}) {
    const tbb::global_control allow(tbb::global_control::max_allowed_parallelism, threads);
    ParticlePool pool = turbulent_pool(20000);
    for (int step = 0; step < 30; ++step) animate_particles(pool, d, env, 1.0f / 30, step / 30.0);
    // The sort of a set that large splits too (key making, the sort, the list).
    ecs::World w;
    w.emplace<ParticleSet>(w.create(), ParticleSet{pool});
    SortScratch scratch;
    DrawList list;
    build_draw_list(w, {0, 1, 8}, {0, 0, -1}, SortKeyKind::eye_distance, scratch, list);
    if (threads == 1) {
      expected_particles = pool_bytes(pool);
      expected_order = list.center_radius;
      EXPECT_GT(pool.size(), 5000u);  // many survived, in several pieces
      continue;
    }
    EXPECT_TRUE(pool_bytes(pool) == expected_particles) << threads << " threads";
    ASSERT_EQ(list.center_radius.size(), expected_order.size());
    EXPECT_EQ(std::memcmp(list.center_radius.data(), expected_order.data(),
                          expected_order.size() * sizeof(glm::vec4)),
              0)
        << threads << " threads";
  }
}

}  // namespace
}  // namespace pyro
