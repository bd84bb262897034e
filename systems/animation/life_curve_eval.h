#pragma once
// Evaluation of a LifeCurve (components/life_curve.h): piecewise linear between keys, constant
// outside them.
#include "components/life_curve.h"

namespace pyro {

inline glm::vec3 evaluate_curve(const LifeCurve& c, float t) {
  const auto& k = c.keys;
  if (k.empty()) return glm::vec3(0.0f);
  if (t <= k.front().t) return k.front().value;
  for (std::size_t i = 1; i < k.size(); ++i) {
    if (t <= k[i].t) {
      const float span = k[i].t - k[i - 1].t;
      const float f = span > 0.0f ? (t - k[i - 1].t) / span : 1.0f;
      return k[i - 1].value + f * (k[i].value - k[i - 1].value);
    }
  }
  return k.back().value;
}

}  // namespace pyro
