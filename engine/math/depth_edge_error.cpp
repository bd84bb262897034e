#include "engine/math/depth_edge_error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "engine/math/color.h"

namespace pyro {

namespace {

void check_size(const char* what, size_t have, size_t want) {
  if (have != want)
    throw std::invalid_argument(std::string("depth edge error: ") + what + " holds " +
                                std::to_string(have) + " values, expected " + std::to_string(want));
}

float clamped(float v) { return std::clamp(v, 0.0f, 1.0f); }

bool same_byte(float a, float b) {
  return to_byte(linear_to_srgb(a)) == to_byte(linear_to_srgb(b));
}

}  // namespace

DepthEdges find_depth_edges(int width, int height, std::span<const float> view_depth,
                            float tolerance) {
  if (width <= 0 || height <= 0)
    throw std::invalid_argument("depth edge error: an empty image (expected width, height > 0)");
  const size_t n = static_cast<size_t>(width) * height;
  check_size("the depth", view_depth.size(), n);
  std::vector<float> u(n);
  for (size_t i = 0; i < n; ++i) {
    if (!(view_depth[i] > 0.0f))
      throw std::invalid_argument("depth edge error: view depth " + std::to_string(view_depth[i]) +
                                  " at pixel " + std::to_string(i) + " (expected > 0)");
    u[i] = 1.0f / view_depth[i];
  }
  DepthEdges e{width, height, std::vector<uint8_t>(n, 0), std::vector<uint8_t>(n, 0)};
  auto mark = [&](size_t at, float second_difference) {
    const float limit = tolerance * u[at];
    if (second_difference < -limit) e.near_side[at] = 1;
    if (second_difference > limit) e.far_side[at] = 1;
  };
  const size_t w = static_cast<size_t>(width);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const size_t at = static_cast<size_t>(y) * w + x;
      if (x > 0 && x + 1 < width) mark(at, u[at - 1] + u[at + 1] - 2.0f * u[at]);
      if (y > 0 && y + 1 < height) mark(at, u[at - w] + u[at + w] - 2.0f * u[at]);
    }
  return e;
}

std::vector<int> chessboard_distance(int width, int height, std::span<const uint8_t> mask) {
  const size_t w = static_cast<size_t>(width);
  check_size("the mask", mask.size(), w * height);
  const int far = std::numeric_limits<int>::max() / 2;
  std::vector<int> d(mask.size());
  for (size_t i = 0; i < mask.size(); ++i) d[i] = mask[i] ? 0 : far;
  auto relax = [&](size_t at, int x, int y) {
    if (x >= 0 && y >= 0 && x < width && y < height)
      d[at] = std::min(d[at], d[static_cast<size_t>(y) * w + x] + 1);
  };
  // Forward over the neighbours already visited (left, and the row above), then backward.
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const size_t at = static_cast<size_t>(y) * w + x;
      relax(at, x - 1, y), relax(at, x - 1, y - 1), relax(at, x, y - 1), relax(at, x + 1, y - 1);
    }
  for (int y = height - 1; y >= 0; --y)
    for (int x = width - 1; x >= 0; --x) {
      const size_t at = static_cast<size_t>(y) * w + x;
      relax(at, x + 1, y), relax(at, x + 1, y + 1), relax(at, x, y + 1), relax(at, x - 1, y + 1);
    }
  return d;
}

DepthEdgeError depth_edge_error(const DepthEdgeInputs& in, const DepthEdgeErrorOptions& o) {
  const DepthEdges edges = find_depth_edges(in.width, in.height, in.view_depth, o.tolerance);
  const size_t n = static_cast<size_t>(in.width) * in.height;
  check_size("the scene", in.scene.size(), 4 * n);
  check_size("the reference", in.reference.size(), 4 * n);
  check_size("the measured image", in.measured.size(), 4 * n);
  if (!in.particle_far.empty()) check_size("the particle depths", in.particle_far.size(), n);
  std::vector<uint8_t> any(n);
  for (size_t i = 0; i < n; ++i) any[i] = edges.near_side[i] | edges.far_side[i];
  const std::vector<int> to_edge = chessboard_distance(in.width, in.height, any);
  const std::vector<int> to_near = chessboard_distance(in.width, in.height, edges.near_side);
  const std::vector<int> to_far = chessboard_distance(in.width, in.height, edges.far_side);
  // Where the reference shows particle light, and which of those pixels lie on a far side, at
  // most halo_bound from its edge.
  std::vector<uint8_t> unlit(n), lit_far(n), lit_near(n);
  for (size_t i = 0; i < n; ++i) {
    bool alone = true;
    for (size_t c = 0; c < 3 && alone; ++c)
      alone = same_byte(in.reference[4 * i + c], in.scene[4 * i + c]);
    unlit[i] = alone;
    lit_far[i] = !alone && to_far[i] < to_near[i] && to_far[i] <= o.halo_bound;
    lit_near[i] = !alone && to_near[i] < to_far[i];
  }
  const std::vector<int> to_lit_far = chessboard_distance(in.width, in.height, lit_far);
  const std::vector<int> to_lit_near = chessboard_distance(in.width, in.height, lit_near);
  DepthEdgeError r;
  double edge_sum = 0.0, halo_sum = 0.0;
  for (size_t i = 0; i < n; ++i) {
    const bool near_edge = to_edge[i] <= o.edge_radius;
    const bool hides = in.particle_far.empty() || in.particle_far[i] > in.view_depth[i];
    const bool halo_pixel = unlit[i] && hides && to_near[i] < to_far[i] &&
                            to_far[i] > o.halo_bound && to_lit_far[i] <= o.halo_reach &&
                            to_lit_far[i] < to_lit_near[i];
    if (!near_edge && !halo_pixel) continue;
    r.edge_pixels += near_edge;
    r.halo_pixels += halo_pixel;
    for (size_t c = 0; c < 3; ++c) {
      const double d = clamped(in.measured[4 * i + c]) - clamped(in.reference[4 * i + c]);
      if (near_edge) edge_sum += d * d;
      if (halo_pixel) {
        halo_sum += d * d;
        r.halo = std::max(r.halo, std::abs(d));
      }
    }
  }
  r.edge_rmse = r.edge_pixels ? std::sqrt(edge_sum / (3.0 * r.edge_pixels)) : 0.0;
  r.halo_rms = r.halo_pixels ? std::sqrt(halo_sum / (3.0 * r.halo_pixels)) : 0.0;
  return r;
}

}  // namespace pyro
