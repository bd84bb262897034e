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

// The signed distance of (x, y, z) from a plane of a ViewFrustum (positive inside).
inline float signed_distance(const glm::vec4& plane, float x, float y, float z) {
  return plane.x * x + plane.y * y + plane.z * z + plane.w;
}

// Whether the sphere at `center` of radius `radius` lies wholly outside one of the planes.
inline bool sphere_outside(const ViewFrustum& f, const glm::vec3& center, float radius) {
  for (const glm::vec4& p : f.planes)
    if (signed_distance(p, center.x, center.y, center.z) < -radius) return true;
  return false;
}

// sphere_outside over arrays, the form the sort uses: seen[i] = 1 where the sphere at (x[i],
// y[i], z[i]) of radius radii * r[i] is not outside one of `views` (every one when `views` is
// empty), else 0; returns how many are seen.
size_t mark_spheres_in_any(std::span<const ViewFrustum> views, const float* x, const float* y,
                           const float* z, const float* r, float radii, size_t n, uint8_t* seen);

}  // namespace pyro
