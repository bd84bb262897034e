#include "engine/math/view_frustum.h"

#include <glm/mat4x4.hpp>

namespace pyro {

namespace {

glm::vec4 normalised(const glm::vec4& plane) {
  const float length = glm::length(glm::vec3(plane));
  return length > 0.0f ? plane / length : plane;
}

}  // namespace

ViewFrustum view_frustum(const CameraFrame& frame) {
  const glm::mat4& m = frame.view_projection;
  // glm is column-major: row r is (m[0][r], m[1][r], m[2][r], m[3][r]).
  auto row = [&m](int r) { return glm::vec4(m[0][r], m[1][r], m[2][r], m[3][r]); };
  ViewFrustum f;
  f.planes[0] = normalised(row(3) + row(0));  // left
  f.planes[1] = normalised(row(3) - row(0));  // right
  f.planes[2] = normalised(row(3) + row(1));  // bottom
  f.planes[3] = normalised(row(3) - row(1));  // top
  f.planes[4] = normalised(row(3) - row(2));  // far
  f.planes[5] = glm::vec4(frame.forward, -glm::dot(frame.forward, frame.eye));  // the eye's plane
  return f;
}

size_t mark_spheres_in_any(std::span<const ViewFrustum> views, const float* __restrict x,
                           const float* __restrict y, const float* __restrict z,
                           const float* __restrict r, float radii, size_t n,
                           uint8_t* __restrict seen) {
  for (size_t i = 0; i < n; ++i) seen[i] = views.empty();
  for (const ViewFrustum& view : views) {
    const std::array<glm::vec4, 6> p = view.planes;  // a local copy: stores to `seen` cannot alias it
    // sphere_outside without its early exit, so that the loop vectorises.
    for (size_t i = 0; i < n; ++i) {
      const float reach = -radii * r[i];
      bool inside = true;
      for (const glm::vec4& q : p) inside &= signed_distance(q, x[i], y[i], z[i]) >= reach;
      seen[i] |= inside;
    }
  }
  size_t count = 0;
  for (size_t i = 0; i < n; ++i) count += seen[i];
  return count;
}

}  // namespace pyro
