#pragma once
// The region of space a view can show, as six planes, for culling particles before they are
// sorted: a particle whose bounding sphere lies wholly outside one plane adds nothing to the
// view's image.
//
// The four side planes and the far plane come from the rows of the view-projection matrix M
// (clip space -w <= x, y, z <= w: left row3 + row0, right row3 - row0, bottom row3 + row1, top
// row3 - row1, far row3 - row2; Gribb & Hartmann 2001, "Fast extraction of viewing frustum
// planes from the world-view-projection matrix"), so an off-axis stereo eye gets its own
// asymmetric frustum. The near plane is replaced by the plane through the eye facing forward:
// the side planes meet at the eye, so a sphere that holds the eye, or reaches between it and
// the near plane, is never outside any plane (the billboards that cover the whole target there
// keep drawing exactly what they drew).
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "engine/math/camera_math.h"

namespace pyro {

struct ViewFrustum {
  // Inside: dot(plane.xyz, p) + plane.w >= 0, plane.xyz a unit normal pointing inwards.
  std::array<glm::vec4, 6> planes{};
};

ViewFrustum view_frustum(const CameraFrame& frame);

// Whether the sphere at `center` of radius `radius` lies wholly outside one of the planes.
inline bool sphere_outside(const ViewFrustum& f, const glm::vec3& center, float radius) {
  for (const glm::vec4& p : f.planes)
    if (p.x * center.x + p.y * center.y + p.z * center.z + p.w < -radius) return true;
  return false;
}

// Whether the sphere can reach any of the views (true when `views` is empty: nothing culls).
inline bool sphere_in_any(std::span<const ViewFrustum> views, const glm::vec3& center,
                          float radius) {
  if (views.empty()) return true;
  for (const ViewFrustum& f : views)
    if (!sphere_outside(f, center, radius)) return true;
  return false;
}

// The same test over arrays, the form the sort uses: seen[i] = 1 where the sphere at (x[i], y[i],
// z[i]) of radius radii * r[i] can reach one of `views` (every one when `views` is empty), else
// 0; returns how many are seen. Written without branches, so that it vectorises.
size_t mark_spheres_in_any(std::span<const ViewFrustum> views, const float* x, const float* y,
                           const float* z, const float* r, float radii, size_t n, uint8_t* seen);

}  // namespace pyro
