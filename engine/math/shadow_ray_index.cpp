#include "engine/math/shadow_ray_index.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

namespace pyro {

void orthonormal_basis(const glm::dvec3& w, glm::dvec3& u, glm::dvec3& v) {
  // Any vector not parallel to w, crossed with it (Hughes & Moller 1999 pick the smallest axis).
  const glm::dvec3 a = std::abs(w.x) < 0.9 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0);
  u = glm::normalize(glm::cross(a, w));
  v = glm::cross(w, u);
}

namespace {

constexpr long kMaxCells = 1L << 22;

double median_reach(const std::vector<ShadowCaster>& casters) {
  std::vector<double> reach;
  reach.reserve(casters.size());
  for (const ShadowCaster& c : casters) reach.push_back(caster_reach(c));
  std::nth_element(reach.begin(), reach.begin() + long(reach.size() / 2), reach.end());
  return reach[reach.size() / 2];
}

}  // namespace

ShadowRayIndex::ShadowRayIndex(std::vector<ShadowCaster> particles, const glm::dvec3& light_travel)
    : particles_(std::move(particles)), toward_light_(-glm::normalize(light_travel)) {
  orthonormal_basis(toward_light_, u_axis_, v_axis_);
  if (particles_.empty()) return;
  double u_lo = std::numeric_limits<double>::max(), v_lo = u_lo, u_hi = -u_lo, v_hi = -u_lo;
  for (const ShadowCaster& g : particles_) {
    const double e = caster_reach(g), u = glm::dot(g.c, u_axis_), v = glm::dot(g.c, v_axis_);
    u_lo = std::min(u_lo, u - e);
    u_hi = std::max(u_hi, u + e);
    v_lo = std::min(v_lo, v - e);
    v_hi = std::max(v_hi, v + e);
  }
  // Cells about a typical particle's projected diameter, fewer when the grid would be too large.
  cell_ = std::max(2.0 * median_reach(particles_), 1e-9);
  while (std::ceil((u_hi - u_lo) / cell_) * std::ceil((v_hi - v_lo) / cell_) > double(kMaxCells))
    cell_ *= 2.0;
  u0_ = u_lo;
  v0_ = v_lo;
  nu_ = std::max(1, int(std::ceil((u_hi - u_lo) / cell_)));
  nv_ = std::max(1, int(std::ceil((v_hi - v_lo) / cell_)));
  // Counting sort of (cell, particle) pairs: each cell's list in the particles' order.
  auto for_each_cell = [&](const ShadowCaster& g, auto&& visit) {
    const double e = caster_reach(g), u = glm::dot(g.c, u_axis_) - u0_, v = glm::dot(g.c, v_axis_) - v0_;
    const int i0 = std::clamp(int(std::floor((u - e) / cell_)), 0, nu_ - 1);
    const int i1 = std::clamp(int(std::floor((u + e) / cell_)), 0, nu_ - 1);
    const int j0 = std::clamp(int(std::floor((v - e) / cell_)), 0, nv_ - 1);
    const int j1 = std::clamp(int(std::floor((v + e) / cell_)), 0, nv_ - 1);
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) visit(size_t(j) * size_t(nu_) + size_t(i));
  };
  starts_.assign(size_t(nu_) * size_t(nv_) + 1, 0);
  for (const ShadowCaster& g : particles_) for_each_cell(g, [&](size_t c) { ++starts_[c + 1]; });
  for (size_t c = 1; c < starts_.size(); ++c) starts_[c] += starts_[c - 1];
  items_.resize(starts_.back());
  std::vector<uint32_t> fill(starts_.begin(), starts_.end() - 1);
  for (size_t k = 0; k < particles_.size(); ++k)
    for_each_cell(particles_[k], [&](size_t c) { items_[fill[c]++] = uint32_t(k); });
}

long ShadowRayIndex::cell_of(double u, double v) const {
  const double fi = std::floor((u - u0_) / cell_), fj = std::floor((v - v0_) / cell_);
  if (!(fi >= 0.0 && fi < nu_ && fj >= 0.0 && fj < nv_)) return -1;
  return long(fj) * nu_ + long(fi);
}

double ShadowRayIndex::optical_depth_to_light(const glm::dvec3& p) const {
  const long c = cell_of(glm::dot(p, u_axis_), glm::dot(p, v_axis_));
  if (c < 0) return 0.0;
  double tau = 0.0;
  for (uint32_t k = starts_[size_t(c)]; k < starts_[size_t(c) + 1]; ++k)
    tau += caster_optical_depth(particles_[items_[k]], p, toward_light_, 0.0,
                                  std::numeric_limits<double>::infinity());
  return tau;
}

}  // namespace pyro
