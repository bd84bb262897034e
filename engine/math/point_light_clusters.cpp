#include "engine/math/point_light_clusters.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

namespace pyro {

namespace {

double weight_of(const PointEmitter& e) {
  return std::max(0.2126 * e.intensity.x + 0.7152 * e.intensity.y + 0.0722 * e.intensity.z, 0.0);
}

double distance2(const glm::dvec3& a, const glm::dvec3& b) {
  const glm::dvec3 d = a - b;
  return glm::dot(d, d);
}

// Farthest-point seeds: the brightest emitter, then each time the one farthest from every seed.
std::vector<glm::dvec3> seeds(const std::vector<PointEmitter>& lit, int count) {
  size_t brightest = 0;
  for (size_t i = 1; i < lit.size(); ++i)
    if (weight_of(lit[i]) > weight_of(lit[brightest])) brightest = i;
  std::vector<glm::dvec3> centres{lit[brightest].position};
  std::vector<double> nearest(lit.size(), std::numeric_limits<double>::max());
  while (int(centres.size()) < count) {
    size_t far = 0;
    for (size_t i = 0; i < lit.size(); ++i) {
      nearest[i] = std::min(nearest[i], distance2(lit[i].position, centres.back()));
      if (nearest[i] > nearest[far]) far = i;
    }
    centres.push_back(lit[far].position);
  }
  return centres;
}

size_t closest(const std::vector<glm::dvec3>& centres, const glm::dvec3& p) {
  size_t best = 0;
  for (size_t c = 1; c < centres.size(); ++c)
    if (distance2(p, centres[c]) < distance2(p, centres[best])) best = c;
  return best;
}

}  // namespace

std::vector<PointEmitter> cluster_point_lights(const std::vector<PointEmitter>& emitters, int count,
                                               int iterations) {
  std::vector<PointEmitter> lit;
  for (const PointEmitter& e : emitters)
    if (weight_of(e) > 0.0) lit.push_back(e);
  if (count <= 0 || lit.empty()) return {};
  if (size_t(count) >= lit.size()) return lit;
  std::vector<glm::dvec3> centres = seeds(lit, count);
  std::vector<size_t> member(lit.size());
  for (int it = 0; it <= iterations; ++it) {
    for (size_t i = 0; i < lit.size(); ++i) member[i] = closest(centres, lit[i].position);
    if (it == iterations) break;
    std::vector<glm::dvec3> sum(centres.size(), glm::dvec3(0.0));
    std::vector<double> weight(centres.size(), 0.0);
    for (size_t i = 0; i < lit.size(); ++i) {
      sum[member[i]] += weight_of(lit[i]) * lit[i].position;
      weight[member[i]] += weight_of(lit[i]);
    }
    for (size_t c = 0; c < centres.size(); ++c)
      if (weight[c] > 0.0) centres[c] = sum[c] / weight[c];
  }
  // Each cluster's light: the weighted centroid, the summed intensity, the rms reach.
  std::vector<PointEmitter> lights(centres.size());
  std::vector<double> weight(centres.size(), 0.0), reach2(centres.size(), 0.0);
  for (size_t i = 0; i < lit.size(); ++i) {
    const size_t c = member[i];
    const double w = weight_of(lit[i]);
    lights[c].position += w * lit[i].position;
    lights[c].intensity += lit[i].intensity;
    weight[c] += w;
  }
  for (size_t c = 0; c < lights.size(); ++c)
    if (weight[c] > 0.0) lights[c].position /= weight[c];
  for (size_t i = 0; i < lit.size(); ++i) {
    const size_t c = member[i];
    reach2[c] += weight_of(lit[i]) * (distance2(lit[i].position, lights[c].position) + lit[i].radius * lit[i].radius);
  }
  std::vector<PointEmitter> out;
  for (size_t c = 0; c < lights.size(); ++c) {
    if (!(weight[c] > 0.0)) continue;
    lights[c].radius = std::sqrt(reach2[c] / weight[c]);
    out.push_back(lights[c]);
  }
  return out;
}

glm::dvec3 point_irradiance(const std::vector<PointEmitter>& emitters, const glm::dvec3& x) {
  glm::dvec3 e(0.0);
  for (const PointEmitter& p : emitters)
    e += p.intensity / std::max(distance2(x, p.position), p.radius * p.radius);
  return e;
}

}  // namespace pyro
