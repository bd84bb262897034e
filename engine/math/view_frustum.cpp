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

}  // namespace pyro
