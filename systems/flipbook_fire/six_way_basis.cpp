#include "systems/flipbook_fire/six_way_basis.h"

#include <glm/geometric.hpp>

namespace pyro {

glm::vec3 six_way_towards_light(SixWayFace f) {
  switch (f) {
    case SixWayFace::right:
      return {1.0f, 0.0f, 0.0f};
    case SixWayFace::top:
      return {0.0f, 1.0f, 0.0f};
    case SixWayFace::back:
      return {0.0f, 0.0f, -1.0f};
    case SixWayFace::left:
      return {-1.0f, 0.0f, 0.0f};
    case SixWayFace::bottom:
      return {0.0f, -1.0f, 0.0f};
    case SixWayFace::front:
      return {0.0f, 0.0f, 1.0f};
  }
  return {0.0f, 0.0f, 1.0f};
}

SixWayValues six_way_weights(const glm::vec3& towards_light) {
  const glm::vec3 w = glm::normalize(towards_light);
  SixWayValues weights{};
  const auto put = [&](float component, SixWayFace positive, SixWayFace negative) {
    weights[static_cast<int>(component >= 0.0f ? positive : negative)] = component * component;
  };
  put(w.x, SixWayFace::right, SixWayFace::left);
  put(w.y, SixWayFace::top, SixWayFace::bottom);
  put(-w.z, SixWayFace::back, SixWayFace::front);  // Unity's local z is away from the viewer
  return weights;
}

float six_way_relight(const SixWayValues& faces, const glm::vec3& towards_light) {
  const SixWayValues weights = six_way_weights(towards_light);
  float sum = 0.0f;
  for (int i = 0; i < kSixWayFaces; ++i) sum += weights[i] * faces[i];
  return sum;
}

}  // namespace pyro
