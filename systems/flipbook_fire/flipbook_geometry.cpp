#include "systems/flipbook_fire/flipbook_geometry.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "engine/math/flipbook_sequence.h"

namespace pyro {

namespace {
// v minus its component along unit n, normalised; zero when too short.
glm::vec3 in_plane(const glm::vec3& v, const glm::vec3& n) {
  const glm::vec3 p = v - n * glm::dot(v, n);
  const float len = glm::length(p);
  return len > 1e-6f ? p / len : glm::vec3(0.0f);
}
}  // namespace

FireFrame face_viewer(const glm::vec3& base, const glm::vec3& up, const glm::vec3& viewer,
                      const glm::vec3& fallback_toward) {
  FireFrame f;
  f.origin = base;
  f.up = glm::normalize(up);
  f.toward = in_plane(viewer - base, f.up);
  if (f.toward == glm::vec3(0.0f)) f.toward = in_plane(fallback_toward, f.up);
  if (f.toward == glm::vec3(0.0f)) {
    // Any perpendicular: the axis least aligned with up, projected.
    const glm::vec3 a = std::fabs(f.up.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 0, 1);
    f.toward = in_plane(a, f.up);
  }
  f.right = glm::normalize(glm::cross(f.up, f.toward));
  return f;
}

std::vector<FlipbookQuad> flipbook_quads(const FlipbookFire& fire, const FireFrame& frame,
                                         int64_t step, int frame_count, float fraction) {
  std::vector<FlipbookQuad> quads;
  quads.reserve(fire.billboards.size());
  const float half = 0.5f * fire.width;
  const glm::vec3 height = frame.up * (fire.width * fire.aspect);
  for (const FlipbookBillboard& b : fire.billboards) {
    FlipbookQuad q;
    const glm::vec3 foot = frame.origin + frame.right * b.lateral + frame.toward * b.depth;
    q.corners[0] = foot - frame.right * half;
    q.corners[1] = foot + frame.right * half;
    q.corners[2] = q.corners[0] + height;
    q.corners[3] = q.corners[1] + height;
    q.frame = flipbook_frame(b.start_frame, b.increment, step, frame_count);
    q.next_frame = flipbook_frame(b.start_frame, b.increment, step + 1, frame_count);
    q.blend = fraction;
    q.motion_scale = static_cast<float>(b.increment);
    q.intensity = b.intensity;
    q.depth = b.depth;
    quads.push_back(q);
  }
  std::stable_sort(quads.begin(), quads.end(),
                   [](const FlipbookQuad& a, const FlipbookQuad& b) { return a.depth < b.depth; });
  return quads;
}

}  // namespace pyro
