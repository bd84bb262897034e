#include "tools/bench/frame_regions.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "systems/runtime/reference/parallel_rows.h"
#include "systems/runtime/reference/pixel_ray.h"

namespace pyro {

namespace {

// Möller & Trumbore 1997: the distance along the ray to the triangle, or -1.
double ray_triangle(const WorldTriangle& t, const glm::dvec3& o, const glm::dvec3& d) {
  const glm::dvec3 e1 = t.b - t.a, e2 = t.c - t.a;
  const glm::dvec3 p = glm::cross(d, e2);
  const double det = glm::dot(e1, p);
  if (std::abs(det) < 1e-14) return -1.0;
  const double inv = 1.0 / det;
  const glm::dvec3 s = o - t.a;
  const double u = glm::dot(s, p) * inv;
  if (u < 0.0 || u > 1.0) return -1.0;
  const glm::dvec3 q = glm::cross(s, e1);
  const double v = glm::dot(d, q) * inv;
  if (v < 0.0 || u + v > 1.0) return -1.0;
  return glm::dot(e2, q) * inv;
}

// The media's extinction at world point p, trilinear between voxel centres (0 outside).
double extinction_at(const MediaVoxels& m, const glm::dvec3& p) {
  const VoxelBox& b = m.box;
  double f[3];
  int i0[3];
  for (int a = 0; a < 3; ++a) {
    const double q = p[a] / b.voxel - b.origin[a];
    const double fl = std::floor(q);
    i0[a] = int(fl);
    f[a] = q - fl;
  }
  double sum = 0.0;
  for (int corner = 0; corner < 8; ++corner) {
    int i[3];
    double w = 1.0;
    for (int a = 0; a < 3; ++a) {
      const int bit = (corner >> a) & 1;
      i[a] = i0[a] + bit;
      w *= bit ? f[a] : 1.0 - f[a];
    }
    if (w == 0.0 || i[0] < 0 || i[1] < 0 || i[2] < 0 || i[0] >= b.dims[0] || i[1] >= b.dims[1] || i[2] >= b.dims[2])
      continue;
    sum += w * m.density[b.at(i[0], i[1], i[2])];
  }
  return sum;
}

// The ray's parameter interval inside the box (empty: t1 < t0).
void box_interval(const glm::dvec3& lo, const glm::dvec3& hi, const glm::dvec3& o, const glm::dvec3& d, double& t0,
                  double& t1) {
  for (int a = 0; a < 3; ++a) {
    if (d[a] == 0.0) {
      if (o[a] < lo[a] || o[a] > hi[a]) t1 = -1.0, t0 = 0.0;
      continue;
    }
    double ta = (lo[a] - o[a]) / d[a], tb = (hi[a] - o[a]) / d[a];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
}

FrameRegion surface_region(const RegionScene& scene, const glm::dvec3& point, const glm::dvec3& view,
                           const WorldTriangle& t) {
  if (glm::length(scene.toward_key) == 0.0) return FrameRegion::lit_surface;
  glm::dvec3 n = glm::normalize(glm::cross(t.b - t.a, t.c - t.a));
  if (glm::dot(n, view) > 0.0) n = -n;  // the side the camera sees
  if (glm::dot(n, scene.toward_key) <= 0.0) return FrameRegion::shadowed_surface;
  const double inf = std::numeric_limits<double>::infinity();
  if (nearest_hit(scene.triangles, point, scene.toward_key, inf).triangle >= 0) return FrameRegion::shadowed_surface;
  const double tau = scene.media ? media_optical_depth(*scene.media, point, scene.toward_key, inf) : 0.0;
  return std::exp(-tau) >= scene.shadow_transmittance ? FrameRegion::lit_surface : FrameRegion::shadowed_surface;
}

}  // namespace

const char* frame_region_name(FrameRegion region) {
  switch (region) {
    case FrameRegion::sky: return "sky";
    case FrameRegion::media: return "media";
    case FrameRegion::lit_surface: return "lit_surface";
    case FrameRegion::shadowed_surface: return "shadowed_surface";
  }
  return "?";
}

RayHit nearest_hit(const std::vector<WorldTriangle>& triangles, const glm::dvec3& origin, const glm::dvec3& dir,
                   double limit) {
  const double start = std::max(1e-6, 1e-5 * glm::length(origin));
  RayHit hit{limit, -1};
  for (size_t i = 0; i < triangles.size(); ++i) {
    const double t = ray_triangle(triangles[i], origin, dir);
    if (t > start && t < hit.distance) hit = {t, int(i)};
  }
  return hit;
}

double media_optical_depth(const MediaVoxels& media, const glm::dvec3& origin, const glm::dvec3& dir, double length) {
  const VoxelBox& b = media.box;
  if (b.voxels() == 0) return 0.0;
  glm::dvec3 lo, hi;
  for (int a = 0; a < 3; ++a) {
    lo[a] = (b.origin[a] - 1) * b.voxel;
    hi[a] = (b.origin[a] + b.dims[a]) * b.voxel;
  }
  double t0 = 0.0, t1 = length;
  box_interval(lo, hi, origin, dir, t0, t1);
  if (!(t1 > t0)) return 0.0;
  const double step = 0.5 * b.voxel;
  const int steps = std::max(1, int(std::ceil((t1 - t0) / step)));
  const double h = (t1 - t0) / steps;
  double tau = 0.0;
  for (int s = 0; s < steps; ++s) tau += extinction_at(media, origin + (t0 + (s + 0.5) * h) * dir);
  return tau * h;
}

std::vector<FrameRegion> frame_regions(const RegionScene& scene, const CameraFrame& camera) {
  std::vector<FrameRegion> regions(size_t(camera.width) * camera.height, FrameRegion::sky);
  const glm::dvec3 eye(camera.eye);
  const double inf = std::numeric_limits<double>::infinity();
  parallel_rows(camera.height, scene.threads, [&](int y) {
    for (int x = 0; x < camera.width; ++x) {
      const glm::dvec3 d = pixel_ray_direction(camera, x + 0.5, y + 0.5);
      const RayHit hit = nearest_hit(scene.triangles, eye, d, inf);
      const double tau = scene.media ? media_optical_depth(*scene.media, eye, d, hit.distance) : 0.0;
      FrameRegion& r = regions[size_t(y) * camera.width + x];
      if (1.0 - std::exp(-tau) >= scene.media_opacity)
        r = FrameRegion::media;
      else if (hit.triangle >= 0)
        r = surface_region(scene, eye + hit.distance * d, d, scene.triangles[size_t(hit.triangle)]);
    }
  });
  return regions;
}

}  // namespace pyro
