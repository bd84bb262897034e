#pragma once
// Which part of a scene each pixel of a frame shows, for scoring a whole frame region by region
// (bench_cycles_scene.h): the media (the camera ray through them is at least `media_opacity`
// opaque), a surface in the key light (its light reaches the surface point with at least
// `shadow_transmittance` through the meshes and the media), a surface in shadow, or the sky.
// Geometry only, independent of either renderer: each pixel's ray through its centre
// (systems/runtime/reference/pixel_ray.h) against every triangle, and the media's optical depth
// marched through their voxels (tools/export/media_voxels.h) at half a voxel, trilinearly.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "engine/math/camera_math.h"
#include "tools/export/media_voxels.h"

namespace pyro {

enum class FrameRegion : uint8_t { sky = 0, media = 1, lit_surface = 2, shadowed_surface = 3 };
inline constexpr int kFrameRegions = 4;

// "sky", "media", "lit_surface", "shadowed_surface".
const char* frame_region_name(FrameRegion region);

struct WorldTriangle {
  glm::dvec3 a, b, c;
};

struct RegionScene {
  std::vector<WorldTriangle> triangles;  // every mesh, in world space
  const MediaVoxels* media = nullptr;    // null: none
  glm::dvec3 toward_key{0.0};            // unit, toward the key light; zero: no key light (all lit)
  double media_opacity = 0.1;
  double shadow_transmittance = 0.5;
  int threads = 0;
};

struct RayHit {
  double distance;  // along the unit ray; the limit when nothing is hit
  int triangle;     // -1 when nothing is hit
};

// The nearest triangle along the unit ray beyond a small start (1e-5 of the origin's distance
// from the world's origin, at least 1e-6) and before `limit`.
RayHit nearest_hit(const std::vector<WorldTriangle>& triangles, const glm::dvec3& origin, const glm::dvec3& dir,
                   double limit);

// The optical depth of the media along the unit ray from `origin` over [0, length] (length may
// be infinite: up to where the ray leaves the voxels).
double media_optical_depth(const MediaVoxels& media, const glm::dvec3& origin, const glm::dvec3& dir, double length);

// One region per pixel, row 0 the top row, for the camera frame's width x height.
std::vector<FrameRegion> frame_regions(const RegionScene& scene, const CameraFrame& camera);

}  // namespace pyro
