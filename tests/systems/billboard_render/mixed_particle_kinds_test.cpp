// Particle sets of different kinds in one scene (components/particle_kind.h): a Gaussian cloud
// and a spherical one interleaved in depth, drawn in one back-to-front order, against the CPU
// reference that integrates both kinds exactly along each ray
// (systems/runtime/reference/particle_sets_reference.h); and a set's own kind overriding the scene-wide
// one, which leaves every other set's pixels as they were.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "components/particle_kind.h"
#include "components/particle_set.h"
#include "engine/math/camera_math.h"
#include "systems/runtime/reference/particle_sets_reference.h"
#include "systems/runtime/reference/world_snapshot.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"

namespace pyro {
namespace {

constexpr int kMixedSize = 80;

CloudDescription mixed_cloud(uint64_t seed, float radius, float density, glm::vec3 color,
                             glm::vec3 lo, glm::vec3 hi) {
  CloudDescription c;
  c.count = 24;
  c.seed = seed;
  c.radius = radius;
  c.density = density;
  c.color = color;
  c.box_min = lo;
  c.box_max = hi;
  return c;
}

SceneDescription mixed_scene() {
  SceneDescription s;
  s.width = s.height = kMixedSize;
  s.background = {0.55f, 0.65f, 0.8f};
  s.camera.position = {0.5f, 0.8f, 7.0f};
  s.camera.target = {0.0f, 0.0f, 0.0f};
  s.camera.fov_y_deg = 40.0f;
  s.camera.near = 1.0f;
  s.camera.far = 20.0f;
  return s;
}

// Both sets in one box, so their particles interleave in depth: a white Gaussian cloud and an
// orange one of spherical particles (density: tau per unit length).
SceneDescription interleaved_scene(std::optional<ParticleShape> second) {
  SceneDescription s = mixed_scene();
  s.clouds.push_back(mixed_cloud(1, 0.55f, 0.35f, {0.95f, 0.95f, 0.95f}, {-1.5f, -0.9f, -1.2f}, {1.5f, 0.9f, 1.2f}));
  s.clouds.push_back(mixed_cloud(2, 0.4f, 2.5f, {0.9f, 0.45f, 0.2f}, {-1.5f, -0.9f, -1.2f}, {1.5f, 0.9f, 1.2f}));
  s.clouds[1].particles = second;
  return s;
}

struct MixedFrame {
  RgbImage image;
  std::vector<ParticlePool> pools;  // each set's particles as drawn, in entity order
  std::vector<ParticleShape> shapes;
};

MixedFrame render_mixed(const SceneDescription& s) {
  SceneRuntime runtime(s, RuntimeOptions{});
  runtime.draw_frame(0);
  MixedFrame out{rgb_of(runtime.image()), {}, {}};
  const ParticleShape scene_wide = s.render.particles;
  runtime.world().each<ParticleSet>([&](ecs::Entity e, ParticleSet& set) {
    out.pools.push_back(set.pool);
    const ParticleKind* kind = runtime.world().try_get<const ParticleKind>(e);
    out.shapes.push_back(kind ? kind->shape : scene_wide);
  });
  return out;
}

RgbImage mixed_reference(const MixedFrame& f, const SceneDescription& s) {
  std::vector<ReferenceParticleSet> sets;
  for (size_t i = 0; i < f.pools.size(); ++i) sets.push_back({&f.pools[i], f.shapes[i]});
  const CameraDescription& c = s.camera;
  const CameraFrame frame = make_camera_frame(c.position, c.target, c.up, c.fov_y_deg, c.near, c.far,
                                              s.width, s.height);
  return render_particle_sets_reference(sets, frame, glm::dvec3(s.background));
}

TEST(MixedParticleKinds, InterleavedGaussianAndSphericalSetsMatchTheReference) {
  const SceneDescription s = interleaved_scene(ParticleShape::spherical);
  const MixedFrame mixed = render_mixed(s);
  ASSERT_EQ(mixed.shapes, (std::vector<ParticleShape>{ParticleShape::gaussian, ParticleShape::spherical}));
  const RgbImage reference = mixed_reference(mixed, s);
  const double rmse = image_rmse(reference, mixed.image);
  // The same particles with the second set's kind ignored (drawn as Gaussians): far off.
  const double ignored = image_rmse(reference, render_mixed(interleaved_scene(std::nullopt)).image);
  std::printf("mixed kinds: rmse %.5f against the reference; %.5f with the kind ignored\n", rmse, ignored);
  EXPECT_LT(rmse, 0.01);  // as splat_vs_particle_reference_test.cpp (the project bar is 0.03)
  EXPECT_GT(ignored, 0.01);
}

// Side by side on screen: a Gaussian cloud on the left and, if `right`, one of the scene-wide
// kind (spherical) on the right, apart.
SceneDescription side_by_side_scene(bool right) {
  SceneDescription s = mixed_scene();
  s.render.particles = ParticleShape::spherical;
  s.clouds.push_back(mixed_cloud(3, 0.35f, 0.5f, {1.0f, 1.0f, 1.0f}, {-2.4f, -0.6f, -0.5f}, {-1.1f, 0.6f, 0.5f}));
  s.clouds.back().particles = ParticleShape::gaussian;
  if (right)
    s.clouds.push_back(mixed_cloud(4, 0.35f, 1.5f, {0.3f, 0.5f, 0.9f}, {1.1f, -0.6f, -0.5f}, {2.4f, 0.6f, 0.5f}));
  return s;
}

// The largest difference between two images over columns [x0, x1).
double largest_difference_in(const RgbImage& a, const RgbImage& b, int x0, int x1) {
  double worst = 0.0;
  for (int y = 0; y < a.height; ++y)
    for (int x = x0; x < x1; ++x)
      for (int c = 0; c < 3; ++c) worst = std::max(worst, double(std::abs(a.at(x, y)[c] - b.at(x, y)[c])));
  return worst;
}

TEST(MixedParticleKinds, ASetsOwnKindOverridesTheSceneWideOne) {
  // render.particles is "spherical"; the left cloud says "gaussian". Its pixels are those of it
  // drawn alone as Gaussians, and the right cloud's those of it drawn alone as spheres.
  const RgbImage both = render_mixed(side_by_side_scene(true)).image;
  const RgbImage left_alone = render_mixed(side_by_side_scene(false)).image;
  // The right cloud alone (a cloud's particles depend on its place in clouds[]: the left one
  // stays, empty and of the scene-wide kind).
  SceneDescription right_only = side_by_side_scene(true);
  right_only.clouds[0].density = 0.0f;
  right_only.clouds[0].particles.reset();
  const RgbImage right_alone = render_mixed(right_only).image;
  SceneDescription left_as_spheres = side_by_side_scene(false);
  left_as_spheres.clouds[0].particles.reset();
  const RgbImage spheres = render_mixed(left_as_spheres).image;
  const int half = kMixedSize / 2;
  EXPECT_LT(largest_difference_in(both, left_alone, 0, half), 1e-4);
  EXPECT_LT(largest_difference_in(both, right_alone, half, kMixedSize), 1e-4);
  // The kinds differ visibly there: ignoring the left cloud's own kind would fail the first check.
  EXPECT_GT(largest_difference_in(left_alone, spheres, 0, half), 0.05);
}

}  // namespace
}  // namespace pyro
