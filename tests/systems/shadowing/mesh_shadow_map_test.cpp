// The meshes' shadow grid (systems/shadowing/mesh_shadow_map.h) against geometry: a square plate
// above the ground under an oblique sun. A point is in its shadow exactly when the ray from it
// toward the sun crosses the plate (a closed form: the ray meets the plate's bottom or top inside
// the square), beyond a texel of the shadow's edge; the plate's own top face is lit (the bias), the
// ground plane casts nothing, and a plate out of the way casts on nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

#include "engine/core/rng.h"
#include "engine/mesh/mesh_data.h"
#include "systems/shadowing/mesh_shadow_map.h"

namespace pyro {
namespace {

const glm::dvec3 kPlateTravel(1.0, -2.0, 0.5);

MeshInstance placed(MeshKind kind, MeshData data, const glm::vec3& position) {
  MeshInstance m;
  m.kind = kind;
  m.geometry = share_mesh(std::move(data), true);
  m.placement.position = position;
  return m;
}

std::vector<MeshInstance> plate_over_ground() {
  return {placed(MeshKind::ground_plane, make_box({-20.0f, -0.01f, -20.0f}, {20.0f, 0.0f, 20.0f}), {0, 0, 0}),
          placed(MeshKind::box, make_box({-1.0f, 0.0f, -1.0f}, {1.0f, 0.1f, 1.0f}), {0, 2, 0})};
}

// How far inside the square the ray from p toward the sun meets the plate's plane at height y
// (negative: outside).
double inside_square(const glm::dvec3& p, double y) {
  const double t = (y - p.y) / -kPlateTravel.y;
  const glm::dvec3 q = p - t * kPlateTravel;
  return std::min(1.0 - std::abs(q.x), 1.0 - std::abs(q.z));
}

// The ray from p toward the sun crosses the thin plate exactly when it crosses its bottom (y = 2)
// or its top (y = 2.1) inside the square: by how far (negative: it passes beside it).
double inside_plate_shadow(const glm::dvec3& p) { return std::max(inside_square(p, 2.0), inside_square(p, 2.1)); }

TEST(MeshShadowMap, APointIsShadowedExactlyWhenItsRayToTheSunCrossesThePlate) {
  MeshShadow shadow;
  build_mesh_shadow_map(plate_over_ground(), kPlateTravel, 512, shadow);
  ASSERT_FALSE(shadow.empty());
  EXPECT_EQ(shadow.version, 1u);
  const double texel = 2.3 / 510.0;  // the plate's extent across the light over 510 texels, about
  Rng rng(3);
  int in = 0, out = 0;
  for (int n = 0; n < 20000; ++n) {
    const glm::dvec3 p(rng.uniform(-3.0f, 4.0f), rng.uniform(0.0f, 1.9f), rng.uniform(-3.0f, 3.0f));
    const double inside = inside_plate_shadow(p);
    if (std::abs(inside) < 3.0 * texel) continue;
    const double v = mesh_visibility(shadow, glm::vec3(p));
    EXPECT_EQ(v, inside > 0.0 ? 0.0 : 1.0) << p.x << ", " << p.y << ", " << p.z << " at " << inside;
    (inside > 0.0 ? in : out) += 1;
  }
  EXPECT_GT(in, 500);
  EXPECT_GT(out, 5000);
  EXPECT_EQ(mesh_visibility(shadow, {0.3f, 2.1f, -0.2f}), 1.0) << "the plate's lit top face";
  EXPECT_EQ(mesh_visibility(shadow, {0.0f, 5.0f, 0.0f}), 1.0) << "above the plate";
  EXPECT_EQ(mesh_visibility(MeshShadow{}, {0.0f, 0.0f, 0.0f}), 1.0) << "no casters";
}

TEST(MeshShadowMap, TheGroundCastsNothingAndAnEmptyGridKeepsCounting) {
  std::vector<MeshInstance> ground = {plate_over_ground().front()};
  MeshShadow shadow;
  build_mesh_shadow_map(plate_over_ground(), kPlateTravel, 64, shadow);
  build_mesh_shadow_map(ground, kPlateTravel, 64, shadow);
  EXPECT_TRUE(shadow.empty());
  EXPECT_EQ(shadow.version, 2u) << "the renderers see that the shadow went";
  EXPECT_FALSE(casts_shadow(MeshKind::ground_plane));
  EXPECT_TRUE(casts_shadow(MeshKind::water_tower));
}

}  // namespace
}  // namespace pyro
