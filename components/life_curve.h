#pragma once
// A piecewise-linear curve over a particle's normalised life t = age / lifetime in [0, 1]:
// keys (t, value) with increasing t, held constant before the first and after the last key.
// Empty means "not set". Scalar curves use value.x. Evaluated by engine/math/life_curve_eval.h.
#include <vector>

#include <glm/vec3.hpp>

namespace pyro {

struct CurveKey {
  float t = 0.0f;
  glm::vec3 value{0.0f};
};

struct LifeCurve {
  std::vector<CurveKey> keys;
};

}  // namespace pyro
