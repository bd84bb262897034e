#include "tools/bench/frame_regions.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "engine/mesh/mesh_data.h"
#include "systems/runtime/reference/pixel_ray.h"

namespace pyro {
namespace {

void append_triangles(const MeshData& mesh, std::vector<WorldTriangle>& out) {
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
    out.push_back({glm::dvec3(mesh.positions[mesh.indices[t]]), glm::dvec3(mesh.positions[mesh.indices[t + 1]]),
                   glm::dvec3(mesh.positions[mesh.indices[t + 2]])});
}

// Whether the ray meets the box [lo, hi] (slabs).
bool ray_meets_box(const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& lo, const glm::dvec3& hi) {
  double t0 = 0.0, t1 = std::numeric_limits<double>::infinity();
  for (int a = 0; a < 3; ++a) {
    double ta = (lo[a] - o[a]) / d[a], tb = (hi[a] - o[a]) / d[a];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  return t1 >= t0;
}

// A box of side 2 between heights 2 and 3 above the ground, a sun toward (0.5, 1, 0): every
// point of the box at height y shadows the ground at x - 0.5 y, so the shadow is exactly
// x in [-2.5, 0], z in [-1, 1]. Seen from straight above, every ground pixel more than a margin
// from that rectangle's edge is classified by it.
TEST(FrameRegions, BoxAboveTheGroundShadowsItsProjectedFootprint) {
  RegionScene scene;
  append_triangles(make_ground_plane(20.0f), scene.triangles);
  const glm::dvec3 lo(-1.0, 2.0, -1.0), hi(1.0, 3.0, 1.0);
  append_triangles(make_box(glm::vec3(lo), glm::vec3(hi)), scene.triangles);
  scene.toward_key = glm::normalize(glm::dvec3(0.5, 1.0, 0.0));
  const CameraFrame camera = make_camera_frame({0.0f, 20.0f, 0.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -1.0f}, 40.0f,
                                               0.1f, 100.0f, 96, 96);
  const std::vector<FrameRegion> regions = frame_regions(scene, camera);
  const double margin = 0.2;  // a pixel's footprint on the ground is 0.15
  int shadowed = 0, lit = 0;
  for (int y = 0; y < camera.height; ++y)
    for (int x = 0; x < camera.width; ++x) {
      const glm::dvec3 d = pixel_ray_direction(camera, x + 0.5, y + 0.5);
      const glm::dvec3 eye(camera.eye);
      if (ray_meets_box(eye, d, lo, hi)) continue;
      const glm::dvec3 g = eye - (eye.y / d.y) * d;
      const double inside = std::min({g.x + 2.5, 0.0 - g.x, g.z + 1.0, 1.0 - g.z});
      if (std::abs(inside) < margin) continue;
      const FrameRegion expected = inside > 0.0 ? FrameRegion::shadowed_surface : FrameRegion::lit_surface;
      EXPECT_EQ(regions[size_t(y) * camera.width + x], expected) << "pixel " << x << ", " << y;
      (inside > 0.0 ? shadowed : lit)++;
    }
  EXPECT_GT(shadowed, 50);
  EXPECT_GT(lit, 1000);
}

MediaVoxels constant_cube(int n, double voxel, float extinction) {
  MediaVoxels m;
  m.box.origin = {-n / 2, -n / 2, -n / 2};
  m.box.dims = {n, n, n};
  m.box.voxel = voxel;
  m.density.assign(m.box.voxels(), extinction);
  return m;
}

// Trilinear between voxel centres, a constant cube of n voxels ramps to 0 over one voxel past its
// last centres: along an axis its optical depth is k n v exactly (two half-voxel ramps of k v / 2).
TEST(FrameRegions, ConstantCubeOpticalDepthIsExtinctionTimesSide) {
  const MediaVoxels m = constant_cube(8, 0.25, 1.5f);
  const glm::dvec3 origin(-10.0, 0.01, -0.02);
  EXPECT_NEAR(media_optical_depth(m, origin, {1.0, 0.0, 0.0}, std::numeric_limits<double>::infinity()),
              1.5 * 8 * 0.25, 1e-9);
  // Cut short at the cube's middle plane x = -0.125 (its centre voxel column's mid-point): half.
  EXPECT_NEAR(media_optical_depth(m, origin, {1.0, 0.0, 0.0}, 10.0 - 0.125), 0.5 * 1.5 * 8 * 0.25, 0.02);
  EXPECT_EQ(media_optical_depth(m, {-10.0, 5.0, 0.0}, {1.0, 0.0, 0.0}, 100.0), 0.0);
}

// A medium above the ground seen through from above is media; the ground beside it, lit by a sun
// straight above, is lit; under it (transmittance e^-3) shadowed.
TEST(FrameRegions, MediaShowAndShadow) {
  RegionScene scene;
  append_triangles(make_ground_plane(20.0f), scene.triangles);
  const MediaVoxels m = constant_cube(8, 0.25, 1.5f);  // [-1.125, 0.875] around the origin, tau 3
  MediaVoxels raised = m;
  raised.box.origin[1] += 16;  // 4 units up
  scene.media = &raised;
  scene.toward_key = {0.0, 1.0, 0.0};
  const CameraFrame camera = make_camera_frame({0.0f, 20.0f, 0.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -1.0f}, 40.0f,
                                               0.1f, 100.0f, 64, 64);
  const std::vector<FrameRegion> regions = frame_regions(scene, camera);
  EXPECT_EQ(regions[size_t(32) * 64 + 31], FrameRegion::media);
  EXPECT_EQ(regions[size_t(2) * 64 + 2], FrameRegion::lit_surface);
  scene.media_opacity = 0.99;  // the camera's ray (tau 3, opacity 0.95) no longer counts as media
  const std::vector<FrameRegion> under = frame_regions(scene, camera);
  EXPECT_EQ(under[size_t(32) * 64 + 31], FrameRegion::shadowed_surface);
}

}  // namespace
}  // namespace pyro
