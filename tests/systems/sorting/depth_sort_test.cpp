// The sorting system: back-to-front order, deterministic tie-breaks, independence from the
// order in which particles and sets were stored.
#include "systems/sorting/depth_sort.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "components/camera.h"
#include "components/draw_list.h"
#include "components/particle_set.h"
#include "components/render_settings.h"
#include "components/stereo_camera.h"
#include "components/view.h"
#include "engine/ecs/schedule.h"
#include "engine/ecs/world.h"
#include "systems/camera/camera_system.h"

namespace pyro {
namespace {

ParticleInit at_depth_sort(float x, float y, float z, float marker) {
  ParticleInit p;
  p.position = {x, y, z};
  p.radius = 0.5f;
  p.density = marker;  // identifies the particle in the draw list
  p.color = {1, 1, 1};
  return p;
}

// The eye frames come from the stereo_camera system (camera phase), as in a scene's schedule;
// both run under the schedule, so their access declarations are checked.
void run_sort(ecs::World& w) {
  if (!w.has_resource<RenderSettings>()) w.set_resource<RenderSettings>();
  ecs::Schedule schedule;
  schedule.add(stereo_camera_system());
  schedule.add(sorting_system());
  schedule.setup(w);
  schedule.run_frame(w);
}

TEST(DepthSort, FarthestFirstAlongTheViewAxis) {
  ecs::World w;
  const ecs::Entity cam = w.create();
  w.emplace<Camera>(cam, Camera{{0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 45, 0.1f, 100, 0});
  const ecs::Entity e = w.create();
  ParticleSet& s = w.emplace<ParticleSet>(e, ParticleSet{ParticlePool(100)});
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(-3, 3), depth(10, 30);  // all inside the 45-degree view
  for (int i = 0; i < 100; ++i) s.pool.spawn(at_depth_sort(u(rng), u(rng), -depth(rng), static_cast<float>(i)));
  run_sort(w);
  const DrawList list = gathered_draw_list(w.resource<EyeDrawLists>(), 0);
  ASSERT_EQ(list.size(), 100u);
  for (size_t k = 1; k < list.size(); ++k)
    EXPECT_LE(list.center_radius[k - 1].z, list.center_radius[k].z);  // -z is forward: far = small z
}

TEST(DepthSort, DepthIsAlongTheViewAxisNotDistance) {
  // Two particles at the same view depth but different distances keep the tie-break order;
  // a particle off-axis but nearer in view depth comes later.
  ecs::World w;
  // A 120-degree view, so that the off-axis particle is still in it.
  w.emplace<Camera>(w.create(), Camera{{0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 120, 0.1f, 100, 0});
  ParticleSet& s = w.emplace<ParticleSet>(w.create(), ParticleSet{ParticlePool(3)});
  s.pool.spawn(at_depth_sort(8, 0, -10, 0));   // distance 12.8, depth 10
  s.pool.spawn(at_depth_sort(0, 0, -10, 1));   // distance 10, depth 10
  s.pool.spawn(at_depth_sort(10, 0, -9, 2));   // distance 13.5, depth 9: nearest in depth
  run_sort(w);
  const DrawList list = gathered_draw_list(w.resource<EyeDrawLists>(), 0);
  ASSERT_EQ(list.size(), 3u);
  EXPECT_EQ(list.color_density[0].w, 0.0f);  // equal depth: lower id first
  EXPECT_EQ(list.color_density[1].w, 1.0f);
  EXPECT_EQ(list.color_density[2].w, 2.0f);
}

TEST(DepthSort, EqualDepthsKeepOneOrderWhateverTheStorageOrder) {
  // Many particles on one plane of constant depth, stored in two different orders and split
  // across sets created in a different order: the draw list must be identical.
  auto build = [](bool reversed) {
    ecs::World w;
    w.emplace<Camera>(w.create(), Camera{{0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 45, 0.1f, 100, 0});
    const ecs::Entity a = w.create();
    const ecs::Entity b = w.create();
    std::vector<ecs::Entity> order = {a, b};
    if (reversed) std::reverse(order.begin(), order.end());
    for (ecs::Entity e : order) {
      ParticleSet& s = w.emplace<ParticleSet>(e, ParticleSet{ParticlePool(50)});
      for (int i = 0; i < 50; ++i) s.pool.spawn(at_depth_sort(static_cast<float>(i % 7), 0, -5, e.index * 100.0f + i));
      if (reversed) {
        // Same ids, different storage order: kill and respawn nothing, just swap-remove the
        // first and re-add it (new id) on one side only would change ids; instead permute
        // storage by swapping entries, which keeps each particle's id.
        for (size_t i = 0; i < 25; ++i) {
          const size_t j = 49 - i;
          std::swap(s.pool.px[i], s.pool.px[j]);
          std::swap(s.pool.density[i], s.pool.density[j]);
          std::swap(s.pool.id[i], s.pool.id[j]);
        }
      }
    }
    run_sort(w);
    return gathered_draw_list(w.resource<EyeDrawLists>(), 0).color_density;
  };
  const auto first = build(false);
  const auto second = build(true);
  ASSERT_EQ(first.size(), second.size());
  for (size_t k = 0; k < first.size(); ++k) EXPECT_EQ(first[k].w, second[k].w) << k;
}

TEST(DepthSort, RepeatedFramesGiveTheSameOrder) {
  ecs::World w;
  w.emplace<Camera>(w.create(), Camera{{0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 45, 0.1f, 100, 0});
  ParticleSet& s = w.emplace<ParticleSet>(w.create(), ParticleSet{ParticlePool(200)});
  for (int i = 0; i < 200; ++i) s.pool.spawn(at_depth_sort(0, 0, -static_cast<float>(i % 3) - 1, static_cast<float>(i)));
  run_sort(w);
  const auto first = gathered_draw_list(w.resource<EyeDrawLists>(), 0).color_density;
  for (int f = 0; f < 5; ++f) {
    run_sort(w);
    const auto again = gathered_draw_list(w.resource<EyeDrawLists>(), 0).color_density;
    for (size_t k = 0; k < first.size(); ++k) ASSERT_EQ(first[k].w, again[k].w);
  }
}

TEST(DepthSort, SortsForTheEyesTheCameraSystemWroteIntoView) {
  // The sort reads View, never the camera: turn View's eye around after the camera system ran
  // and the order reverses, though the camera entity still looks down -z.
  ecs::World w;
  w.emplace<Camera>(w.create(), Camera{{0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 45, 0.1f, 100, 0});
  ParticleSet& s = w.emplace<ParticleSet>(w.create(), ParticleSet{ParticlePool(5)});
  for (int i = 0; i < 5; ++i)
    s.pool.spawn(at_depth_sort(0, 0, -2.0f - static_cast<float>(i), static_cast<float>(i)));
  run_sort(w);
  const auto order = [&] {
    std::vector<float> markers;
    for (const glm::vec4& c : gathered_draw_list(w.resource<EyeDrawLists>(), 0).color_density)
      markers.push_back(c.w);
    return markers;
  };
  EXPECT_EQ(order(), (std::vector<float>{4, 3, 2, 1, 0}));  // farthest (most negative z) first

  View& view = w.resource<View>();
  view.eyes.at(0).eye = {0, 0, -10};
  view.eyes.at(0).forward = {0, 0, 1};
  ecs::Schedule sort_only;
  sort_only.add(sorting_system());
  sort_only.setup(w);
  sort_only.run_frame(w);
  EXPECT_EQ(order(), (std::vector<float>{0, 1, 2, 3, 4}));
  // The sort may not touch the camera at all: its declaration has no Camera.
  EXPECT_EQ(sorting_system().access.mode(ecs::type_id<Camera>()), ecs::AccessMode::none);
}

TEST(DepthSort, IndexedListsHoldTheGatheredOrderForEveryShapeAndAlignment) {
  // Gaussian splats get indexed lists (records + order), the other shapes gathered ones; both
  // must list the same particles in the same order, facing the viewplane (one shared order) and
  // the viewpoint (one order per eye).
  ecs::World w;
  w.emplace<Camera>(w.create(), Camera{{0.5f, 1, 3}, {0, 0, -1}, {0, 1, 0}, 45, 0.1f, 100, 0});
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(-4, 4);
  for (int set = 0; set < 3; ++set) {
    ParticleSet& s = w.emplace<ParticleSet>(w.create(), ParticleSet{ParticlePool(400)});
    for (int i = 0; i < 400; ++i)
      s.pool.spawn(at_depth_sort(u(rng), u(rng), std::round(u(rng)) - 8, static_cast<float>(set * 1000 + i)));
  }
  for (const BillboardAlignment alignment : {BillboardAlignment::viewplane, BillboardAlignment::viewpoint}) {
    RenderSettings settings;
    settings.alignment = alignment;
    settings.stereo_mode = StereoMode::side_by_side;
    settings.particles = ParticleShape::gaussian;
    w.set_resource<RenderSettings>(settings);
    run_sort(w);
    const EyeDrawLists indexed = w.resource<EyeDrawLists>();
    settings.particles = ParticleShape::spherical;
    w.set_resource<RenderSettings>(settings);
    run_sort(w);
    const EyeDrawLists& gathered = w.resource<EyeDrawLists>();
    ASSERT_EQ(indexed.eyes.size(), 2u);
    ASSERT_EQ(gathered.eyes.size(), 2u);
    for (size_t eye = 0; eye < 2; ++eye) {
      ASSERT_TRUE(indexed.eyes[eye].indexed());
      ASSERT_FALSE(gathered.eyes[eye].indexed());
      const DrawList from_records = gathered_draw_list(indexed, eye);
      // Some particles lie outside the views and are left out, alike in both forms.
      ASSERT_EQ(from_records.size(), gathered.eyes[eye].size());
      EXPECT_GT(from_records.size(), 600u);
      EXPECT_LT(from_records.size(), 1200u);
      EXPECT_TRUE(from_records.center_radius == gathered.eyes[eye].center_radius) << eye;
      EXPECT_TRUE(from_records.color_density == gathered.eyes[eye].color_density) << eye;
    }
  }
}

// Culling: particles whose bounding sphere (two radii) lies outside the view are left out
// before the sort; those whose sphere reaches into it stay, in their order.
TEST(DepthSort, LeavesOutWhatNoViewCanShow) {
  ecs::World w;
  // 90 degrees, square: the view holds |x| <= depth and |y| <= depth.
  Camera camera{{0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 90, 0.1f, 100, 0};
  w.emplace<Camera>(w.create(), camera);
  RenderSettings settings;
  settings.width = settings.height = 64;
  settings.particles = ParticleShape::gaussian;
  w.set_resource<RenderSettings>(settings);
  ParticleSet& s = w.emplace<ParticleSet>(w.create(), ParticleSet{ParticlePool(8)});
  s.pool.spawn(at_depth_sort(0, 0, -10, 0));       // in front: kept
  s.pool.spawn(at_depth_sort(0, 0, 10, 1));        // behind the eye: out
  s.pool.spawn(at_depth_sort(12, 0, -10, 2));      // 2 / sqrt(2) = 1.41 right of the view's side: out
  s.pool.spawn(at_depth_sort(10.6f, 0, -10, 3));   // 0.42 outside, within two radii (1.0): kept
  s.pool.spawn(at_depth_sort(0, 0, -102, 4));      // beyond the far plane by 2 (> 1.0): out
  s.pool.spawn(at_depth_sort(0, 0, -100.5f, 5));   // beyond it by 0.5: kept
  s.pool.spawn(at_depth_sort(0, 0, 0.8f, 6));      // behind the eye by 0.8, within 1.0: kept
  s.pool.spawn(at_depth_sort(0, -30, -10, 7));     // below: out
  run_sort(w);
  const DrawList list = gathered_draw_list(w.resource<EyeDrawLists>(), 0);
  std::vector<float> kept;
  for (const glm::vec4& c : list.color_density) kept.push_back(c.w);
  EXPECT_EQ(kept, (std::vector<float>{5, 0, 3, 6}));  // far to near
  // The gathered form (spherical billboards) keeps the same ones.
  settings.particles = ParticleShape::spherical;
  w.set_resource<RenderSettings>(settings);
  run_sort(w);
  std::vector<float> gathered;
  for (const glm::vec4& c : w.resource<EyeDrawLists>().eyes.at(0).color_density) gathered.push_back(c.w);
  EXPECT_EQ(gathered, kept);
}

TEST(DepthSort, AStereoPairSharesTheParticlesEitherEyeSees) {
  // Facing the viewplane the eyes share one list: a particle only one eye sees stays in it.
  // Facing the viewpoint each eye has its own list and keeps only what it sees.
  ecs::World w;
  const ecs::Entity cam = w.create();
  w.emplace<Camera>(cam, Camera{{0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 40, 0.1f, 100, 0});
  w.emplace<StereoCamera>(cam, StereoCamera{{8.0f, 10.0f}});  // eyes at x = -4 and +4
  ParticleSet& s = w.emplace<ParticleSet>(w.create(), ParticleSet{ParticlePool(3)});
  s.pool.spawn(at_depth_sort(0, 0, -10, 0));
  for (const BillboardAlignment alignment : {BillboardAlignment::viewplane, BillboardAlignment::viewpoint}) {
    RenderSettings settings;
    settings.width = 200;
    settings.height = 100;
    settings.alignment = alignment;
    settings.stereo_mode = StereoMode::side_by_side;
    settings.particles = ParticleShape::gaussian;
    w.set_resource<RenderSettings>(settings);
    run_sort(w);
    const View& view = w.resource<View>();
    ASSERT_EQ(view.eyes.size(), 2u);
    // A particle the right eye sees and the left does not: found from the frusta themselves.
    const ViewFrustum left = view_frustum(view.eyes[0]), right = view_frustum(view.eyes[1]);
    glm::vec3 only_right{-40, 0, -30};  // beyond the zero-parallax plane, where the frusta part
    for (float x = -40; x < 40 && !(sphere_outside(left, only_right, 1.0f) && !sphere_outside(right, only_right, 1.0f)); x += 0.05f)
      only_right.x = x;
    ASSERT_TRUE(sphere_outside(left, only_right, 1.0f));
    ASSERT_FALSE(sphere_outside(right, only_right, 1.0f));
    if (s.pool.size() == 1) s.pool.spawn(at_depth_sort(only_right.x, only_right.y, only_right.z, 1));
    s.pool.px[1] = only_right.x;
    run_sort(w);
    const EyeDrawLists& lists = w.resource<EyeDrawLists>();
    const size_t left_count = lists.eyes.at(0).size(), right_count = lists.eyes.at(1).size();
    if (alignment == BillboardAlignment::viewplane) {
      EXPECT_EQ(left_count, 2u);
      EXPECT_EQ(right_count, 2u);
    } else {
      EXPECT_EQ(left_count, 1u);
      EXPECT_EQ(right_count, 2u);
    }
  }
}

}  // namespace
}  // namespace pyro
