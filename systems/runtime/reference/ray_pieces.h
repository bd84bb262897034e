#pragma once
// The colour a pixel ray gathers through overlapping Gaussian particles, shared by the CPU
// references (particle_reference.h, anisotropic_reference.h).
//
// Each particle on the ray contributes an interval [a, b] where it is non-zero and a way to give
// its optical depth over any sub-interval in closed form. The ray is cut at every interval's
// ends and at each particle's closest approach (where its density peaks); each piece between
// two cuts is split into parts of optical depth at most `max_piece_depth`, and each part, front
// to back, adds T (1 - exp(-dtau)) times the dtau-weighted mean colour of the particles in it and
// multiplies the transmittance T by exp(-dtau). Optical depth is exact; the colour mixing is exact
// for one colour and converges as the parts shrink.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include <glm/vec3.hpp>

namespace pyro {

class RayPieces {
 public:
  void clear() {
    hits_.clear();
    cuts_.clear();
  }

  // Particle `element` is non-zero on [a, b] (b > a) and peaks at t_closest.
  void add(double a, double b, double t_closest, std::size_t element) {
    hits_.push_back({a, b, element});
    cuts_.push_back(a);
    cuts_.push_back(b);
    if (t_closest > a && t_closest < b) cuts_.push_back(t_closest);
  }

  // depth(element, a, b): that particle's optical depth over [a, b]; colour(element): its linear
  // colour; behind: what the ray meets after the medium. Returns the pixel's radiance.
  template <class Depth, class Colour>
  glm::dvec3 integrate(Depth&& depth, Colour&& colour, const glm::dvec3& behind,
                       double max_piece_depth) {
    return integrate(depth, colour, behind, max_piece_depth,
                     [](double, double) { return glm::dvec3(1.0); });
  }

  // The same with the colour of each part [a, b] multiplied by light(a, b): the light reaching
  // the part (a lit medium's albedo times its light).
  template <class Depth, class Colour, class Light>
  glm::dvec3 integrate(Depth&& depth, Colour&& colour, const glm::dvec3& behind,
                       double max_piece_depth, Light&& light) {
    return integrate(depth, colour, behind, max_piece_depth, light,
                     [](std::size_t) { return glm::dvec3(0.0); });
  }

  // The same with each particle also emitting emission(element), unlit (a fire's radiance L_e,
  // engine/math/temperature_emission.h): a part adds the dtau-weighted mean of its particles'
  // L_e times its opacity, so one particle of constant L_e adds exactly L_e (1 - exp(-tau)).
  template <class Depth, class Colour, class Light, class Emission>
  glm::dvec3 integrate(Depth&& depth, Colour&& colour, const glm::dvec3& behind,
                       double max_piece_depth, Light&& light, Emission&& emission) {
    glm::dvec3 radiance(0.0);
    double transmittance = 1.0;
    std::sort(cuts_.begin(), cuts_.end());
    // A sweep along the ray: `active_` holds the particles that cover the current piece, in the
    // order they were added (so every sum runs in the same order as over all particles). Every
    // interval end is a cut, so particle h covers [a, b] (consecutive cuts, a < b) exactly when
    // h.a <= a and h.b > a.
    starts_.resize(hits_.size());
    for (std::size_t i = 0; i < hits_.size(); ++i) starts_[i] = i;
    std::sort(starts_.begin(), starts_.end(), [&](std::size_t x, std::size_t y) {
      return hits_[x].a != hits_[y].a ? hits_[x].a < hits_[y].a : x < y;
    });
    active_.clear();
    std::size_t next_start = 0;
    for (std::size_t c = 0; c + 1 < cuts_.size() && transmittance > 1e-7; ++c) {
      const double a = cuts_[c], b = cuts_[c + 1];
      if (b <= a) continue;
      for (; next_start < starts_.size() && hits_[starts_[next_start]].a <= a; ++next_start)
        active_.insert(std::lower_bound(active_.begin(), active_.end(), starts_[next_start]),
                       starts_[next_start]);
      std::erase_if(active_, [&](std::size_t h) { return hits_[h].b <= a; });
      // The optical depth of the whole piece decides how finely it is split for colour mixing.
      double total = 0.0;
      for (std::size_t h : active_) total += depth(hits_[h].element, a, b);
      const int parts = std::max(1, int(std::ceil(total / max_piece_depth)));
      for (int k = 0; k < parts; ++k) {
        const double pa = a + (b - a) * k / parts, pb = a + (b - a) * (k + 1) / parts;
        double dtau = 0.0;
        glm::dvec3 col(0.0), emitted(0.0);
        for (std::size_t h : active_) {
          const double t = depth(hits_[h].element, pa, pb);
          dtau += t;
          col += t * colour(hits_[h].element);
          emitted += t * emission(hits_[h].element);
        }
        if (dtau <= 0.0) continue;
        const double alpha = -std::expm1(-dtau);
        radiance += transmittance * alpha * ((col / dtau) * light(pa, pb) + emitted / dtau);
        transmittance *= 1.0 - alpha;
      }
    }
    return radiance + transmittance * behind;
  }

 private:
  struct Hit {
    double a, b;
    std::size_t element;
  };
  std::vector<Hit> hits_;
  std::vector<double> cuts_;
  std::vector<std::size_t> starts_, active_;  // integrate's sweep, kept to reuse their memory
};

}  // namespace pyro
