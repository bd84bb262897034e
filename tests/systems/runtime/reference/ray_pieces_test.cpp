// The ray's piece-by-piece mixing (systems/runtime/reference/ray_pieces.h): one uniform element is
// Beer-Lambert exactly; for many overlapping elements the sweep gives bit for bit what visiting
// every element for every piece gives (the same elements, summed in the same order).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "engine/core/rng.h"
#include "systems/runtime/reference/ray_pieces.h"

namespace pyro {
namespace {

struct Element {
  double a, b, peak_at, k;
  glm::dvec3 colour;
};

// A smooth bump of extinction 6 k (t - a)(b - t) / (b - a)^2 over [a, b] (mean k), integrated
// exactly: its antiderivative is k (t - a)^2 (3 (b - a) - 2 (t - a)) / (b - a)^2.
double bump_depth(const Element& e, double a, double b) {
  const auto f = [&](double t) {
    t = std::clamp(t, e.a, e.b);
    const double u = t - e.a, l = e.b - e.a;
    return e.k * u * u * (3.0 * l - 2.0 * u) / (l * l);
  };
  return f(b) - f(a);
}

// Every element visited for every piece (the mixing as the references first wrote it).
glm::dvec3 brute_force(const std::vector<Element>& es, const glm::dvec3& behind, double max_piece) {
  std::vector<double> cuts;
  for (const Element& e : es) {
    cuts.push_back(e.a);
    cuts.push_back(e.b);
    if (e.peak_at > e.a && e.peak_at < e.b) cuts.push_back(e.peak_at);
  }
  std::sort(cuts.begin(), cuts.end());
  glm::dvec3 radiance(0.0);
  double transmittance = 1.0;
  for (std::size_t c = 0; c + 1 < cuts.size() && transmittance > 1e-7; ++c) {
    const double a = cuts[c], b = cuts[c + 1];
    if (b <= a) continue;
    double total = 0.0;
    for (const Element& e : es)
      if (e.a <= a && e.b >= b) total += bump_depth(e, a, b);
    const int parts = std::max(1, int(std::ceil(total / max_piece)));
    for (int k = 0; k < parts; ++k) {
      const double pa = a + (b - a) * k / parts, pb = a + (b - a) * (k + 1) / parts;
      double dtau = 0.0;
      glm::dvec3 col(0.0);
      for (const Element& e : es)
        if (e.a <= a && e.b >= b) {
          const double t = bump_depth(e, pa, pb);
          dtau += t;
          col += t * e.colour;
        }
      if (dtau <= 0.0) continue;
      const double alpha = -std::expm1(-dtau);
      radiance += transmittance * alpha * (col / dtau);
      transmittance *= 1.0 - alpha;
    }
  }
  return radiance + transmittance * behind;
}

glm::dvec3 swept(RayPieces& pieces, const std::vector<Element>& es, const glm::dvec3& behind, double max_piece) {
  pieces.clear();
  for (std::size_t i = 0; i < es.size(); ++i) pieces.add(es[i].a, es[i].b, es[i].peak_at, i);
  return pieces.integrate([&](std::size_t i, double a, double b) { return bump_depth(es[i], a, b); },
                          [&](std::size_t i) { return es[i].colour; }, behind, max_piece);
}

TEST(RayPieces, OneElementIsBeerLambert) {
  const std::vector<Element> es = {{1.0, 3.0, 2.0, 0.7, {1.0, 0.5, 0.25}}};
  RayPieces pieces;
  const glm::dvec3 behind(0.2, 0.4, 0.6);
  const glm::dvec3 got = swept(pieces, es, behind, 0.02);
  const double t = std::exp(-0.7 * 2.0);  // total depth k (b - a)
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], es[0].colour[c] * (1.0 - t) + behind[c] * t, 1e-14);
}

TEST(RayPieces, TheSweepIsTheBruteForceMixingBitForBit) {
  Rng rng(12);
  RayPieces pieces;  // reused, as the references reuse one per row
  for (int ray = 0; ray < 200; ++ray) {
    std::vector<Element> es;
    const int n = 1 + ray % 40;
    for (int i = 0; i < n; ++i) {
      Element e;
      e.a = rng.uniform(0.0f, 10.0f);
      e.b = e.a + rng.uniform(0.01f, 3.0f);
      if (i % 7 == 3 && !es.empty()) e.a = es.back().a;  // shared ends
      if (i % 5 == 4 && !es.empty()) e.b = std::max(es.back().b, e.a + 0.01);
      e.peak_at = e.a + (e.b - e.a) * rng.uniform();
      e.k = rng.uniform(0.0f, 2.0f);
      e.colour = {rng.uniform(), rng.uniform(), rng.uniform()};
      es.push_back(e);
    }
    const glm::dvec3 behind(0.3, 0.5, 0.7);
    const glm::dvec3 want = brute_force(es, behind, 0.05), got = swept(pieces, es, behind, 0.05);
    EXPECT_EQ(got.x, want.x) << ray;
    EXPECT_EQ(got.y, want.y) << ray;
    EXPECT_EQ(got.z, want.z) << ray;
  }
}

}  // namespace
}  // namespace pyro
