#pragma once
// Many small emitters (the fire particles of an explosion) stood for by a few point lights, so
// that a shader lights every fragment with a handful of terms instead of one per emitter.
//
// An emitter is a point source of intensity I (linear rgb, per steradian) with a size r below
// which its irradiance stops growing: E(x) = I / max(|x - p|^2, r^2) (inside an emitting sphere
// the point-source law no longer holds; this is the model the lights and their truth share). The
// clusters are a k-means (Lloyd 1982) on the emitters' positions weighted by their luminance,
// seeded by farthest-point sampling from the brightest: deterministic, whatever the threads.
// Each light sits at its emitters' weighted centroid with their summed intensity, so the total
// intensity is conserved exactly, and far from a cluster its light is its emitters' to first
// order; its size is the weighted root-mean-square reach of its emitters about the centroid.
#include <vector>

#include <glm/vec3.hpp>

namespace pyro {

struct PointEmitter {
  glm::dvec3 position{0.0};
  glm::dvec3 intensity{0.0};  // linear rgb, per steradian
  double radius = 0.0;        // the irradiance is held below I / radius^2
};

// At most `count` lights for `emitters` (no more than there are emitters with intensity; none for
// count <= 0). With count at least the number of such emitters, each is its own light.
std::vector<PointEmitter> cluster_point_lights(const std::vector<PointEmitter>& emitters, int count,
                                               int iterations = 8);

// The irradiance at x of every emitter: sum I / max(|x - p|^2, r^2) (direction not weighed).
glm::dvec3 point_irradiance(const std::vector<PointEmitter>& emitters, const glm::dvec3& x);

}  // namespace pyro
