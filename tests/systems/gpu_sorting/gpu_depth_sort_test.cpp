// The draw order made by compute shaders (systems/gpu_sorting) is the sorting system's own:
// for random, equal-depth, nearly sorted and -0/+0 input, several sets with ids out of order,
// culled against one or two frusta or not at all, by view depth and by distance to the eye, and
// over many radix blocks, the GPU's indices equal order_draw_list's (the CPU radix order, itself
// checked against std::sort in radix_sort_test.cpp) one for one.
#include "systems/gpu_sorting/gpu_depth_sort.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include <glm/vec4.hpp>

#include "engine/math/camera_math.h"
#include "engine/math/view_frustum.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"
#include "systems/sorting/depth_sort.h"

namespace pyro {
namespace {

struct Case {
  std::vector<ParticlePool> pools;
  GpuOrderRequest request;
};

ParticleInit particle_at(const glm::vec3& p, float radius) {
  ParticleInit init;
  init.position = p;
  init.radius = radius;
  init.density = 0.5f;
  init.color = {1, 1, 1};
  return init;
}

// Spawns `count` particles from `where(i)`, then kills every third by swapping the last in (so
// the pool's ids are no longer in index order), then spawns a few more.
template <class Where>
ParticlePool pool_of(size_t count, Where where) {
  ParticlePool pool(count + count / 8 + 8);
  for (size_t i = 0; i < count; ++i) pool.spawn(particle_at(where(i), 0.05f));
  for (size_t i = 0; i < pool.size(); i += 3) pool.kill(i);
  for (size_t i = 0; i < count / 8; ++i) pool.spawn(particle_at(where(count + i), 0.05f));
  return pool;
}

std::vector<const ParticlePool*> pointers(const Case& c) {
  std::vector<const ParticlePool*> out;
  for (const ParticlePool& p : c.pools) out.push_back(&p);
  return out;
}

std::vector<uint32_t> cpu_order(const Case& c) {
  SortScratch scratch;
  for (size_t s = 0; s < c.pools.size(); ++s) scratch.sets.emplace_back(uint32_t(10 + s), &c.pools[s]);
  DrawList list;
  const GpuOrderRequest& r = c.request;
  order_draw_list(r.eye, r.forward, r.by_eye_distance ? SortKeyKind::eye_distance : SortKeyKind::view_depth,
                  scratch, list, r.views);
  return list.order;
}

std::vector<uint32_t> gpu_order(const Case& c) {
  shared_headless_context().make_current();
  std::vector<glm::vec4> records;
  std::vector<uint32_t> ids;
  GpuParticles in;
  in.set_starts.push_back(0);
  for (const ParticlePool& p : c.pools) {
    for (size_t i = 0; i < p.size(); ++i) {
      records.push_back({p.px[i], p.py[i], p.pz[i], p.radius[i]});
      records.push_back({p.r[i], p.g[i], p.b[i], p.density[i]});
      ids.push_back(p.id[i]);
    }
    in.set_starts.push_back(uint32_t(ids.size()));
  }
  gpu::Buffer record_buffer = gpu::make_buffer(), id_buffer = gpu::make_buffer();
  glNamedBufferStorage(record_buffer.get(), GLsizeiptr(records.size() * sizeof(glm::vec4)) + 32,
                       records.data(), 0);
  glNamedBufferStorage(id_buffer.get(), GLsizeiptr(ids.size() * sizeof(uint32_t)) + 4, ids.data(), 0);
  in.records = {record_buffer.get(), 0, GLsizeiptr(records.size() * sizeof(glm::vec4)) + 32};
  in.ids = {id_buffer.get(), 0, GLsizeiptr(ids.size() * sizeof(uint32_t)) + 4};
  in.layout = gpu_key_layout(pointers(c));
  GpuDepthSort sort;
  sort.order(in, c.request);
  return sort.read_order();
}

void expect_same_order(const Case& c, const char* what) {
  const std::vector<uint32_t> cpu = cpu_order(c), gpu = gpu_order(c);
  ASSERT_EQ(gpu.size(), cpu.size()) << what;
  size_t differ = 0;
  for (size_t k = 0; k < cpu.size(); ++k) differ += gpu[k] != cpu[k];
  EXPECT_EQ(differ, 0u) << what << ": " << differ << " of " << cpu.size() << " entries differ";
}

CameraFrame camera_at_gpu_depth_sort(const glm::vec3& eye, const glm::vec3& target) {
  return make_camera_frame(eye, target, {0, 1, 0}, 50.0f, 0.1f, 100.0f, 64, 48);
}

GpuOrderRequest request_for(const CameraFrame& f, bool by_eye_distance, bool cull) {
  GpuOrderRequest r{f.eye, f.forward, by_eye_distance, {}};
  if (cull) r.views.push_back(view_frustum(f));
  return r;
}

TEST(GpuDepthSort, RandomParticlesInThreeSetsCulledByOneView) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-20.0f, 20.0f);
  Case c;
  for (int s = 0; s < 3; ++s) c.pools.push_back(pool_of(3000 + 1000 * s, [&](size_t) {
    return glm::vec3(u(rng), u(rng), u(rng));
  }));
  c.request = request_for(camera_at_gpu_depth_sort({0, 0, 5}, {0, 0, 0}), false, true);
  expect_same_order(c, "random, culled");
  EXPECT_LT(cpu_order(c).size(), 12000u);  // some were culled
  EXPECT_GT(cpu_order(c).size(), 500u);
}

TEST(GpuDepthSort, EqualDepthsFallBackOnTheSetThenTheId) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-2.0f, 2.0f);
  Case c;
  // On the plane z = -10, facing the camera: every view depth is the same.
  for (int s = 0; s < 2; ++s)
    c.pools.push_back(pool_of(5000, [&](size_t) { return glm::vec3(u(rng), u(rng), -10.0f); }));
  c.request = request_for(camera_at_gpu_depth_sort({0, 0, 0}, {0, 0, -1}), false, true);
  expect_same_order(c, "equal depths");
}

TEST(GpuDepthSort, NearlySortedInputOverManyBlocks) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> jitter(-0.01f, 0.01f), u(-1.0f, 1.0f);
  Case c;
  // Back to front already, with small swaps: over 20 radix blocks of 4096.
  c.pools.push_back(pool_of(90000, [&](size_t i) {
    return glm::vec3(u(rng), u(rng), -50.0f + float(i % 90000) * 0.0005f + jitter(rng));
  }));
  c.request = request_for(camera_at_gpu_depth_sort({0, 0, 0}, {0, 0, -1}), false, false);
  expect_same_order(c, "nearly sorted");
}

TEST(GpuDepthSort, DistanceToTheEyeCulledByTwoEyes) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<float> u(-10.0f, 10.0f);
  Case c;
  for (int s = 0; s < 4; ++s)
    c.pools.push_back(pool_of(2500, [&](size_t) { return glm::vec3(u(rng), u(rng), u(rng) - 12.0f); }));
  const CameraFrame left = camera_at_gpu_depth_sort({-0.3f, 0, 0}, {-0.3f, 0, -1}), right = camera_at_gpu_depth_sort({0.3f, 0, 0}, {0.3f, 0, -1});
  c.request = request_for(left, true, true);
  c.request.views.push_back(view_frustum(right));
  expect_same_order(c, "eye distance, two views");
}

TEST(GpuDepthSort, NegativeAndPositiveZeroDepthsAreOneKey) {
  Case c;
  // Particles in the eye's plane, looking down -z: the depth dx * 0 + dy * 0 + dz * -1 is -0
  // where x < 0, y < 0 and z = +0, else +0; mixed with small depths of both signs.
  c.pools.push_back(pool_of(3000, [](size_t i) {
    const float z = i % 3 == 0 ? 0.0f : (i % 3 == 1 ? -0.0f : (i % 2 ? 1e-3f : -1e-3f));
    return glm::vec3(float(i % 17) * 0.1f - 0.85f, float(i % 5) * 0.1f - 0.25f, z);
  }));
  c.request = request_for(camera_at_gpu_depth_sort({0, 0, 0}, {0, 0, -1}), false, false);
  expect_same_order(c, "-0 and +0");
}

TEST(GpuDepthSort, NoParticleInViewKeepsNone) {
  Case c;
  c.pools.push_back(pool_of(100, [](size_t i) { return glm::vec3(float(i), 0.0f, 50.0f); }));  // behind
  c.request = request_for(camera_at_gpu_depth_sort({0, 0, 0}, {0, 0, -1}), false, true);
  EXPECT_TRUE(gpu_order(c).empty());
  EXPECT_TRUE(cpu_order(c).empty());
}

}  // namespace
}  // namespace pyro
