#include "systems/flipbook_fire/flipbook_pattern.h"

#include <cmath>
#include <cstdlib>

#include "engine/math/flipbook_sequence.h"

namespace pyro {

namespace {
bool neighbours(const FlipbookBillboard& a, const FlipbookBillboard& b) {
  if (a.group != b.group) return false;
  const int dr = std::abs(a.row - b.row), dc = std::abs(a.column - b.column);
  return dr + dc == 1;
}
}  // namespace

PatternMotion measure_pattern_motion(const std::vector<FlipbookBillboard>& billboards,
                                     int frame_count) {
  PatternMotion m;
  if (billboards.empty() || frame_count <= 0) return m;
  glm::dvec2 centroid(0.0);
  for (const FlipbookBillboard& b : billboards) centroid += glm::dvec2(b.lateral, b.depth);
  centroid /= static_cast<double>(billboards.size());
  glm::dvec2 sum(0.0);
  double tangential = 0.0;
  long long transfers = 0;
  for (size_t a = 0; a < billboards.size(); ++a) {
    for (size_t b = 0; b < billboards.size(); ++b) {
      if (a == b || !neighbours(billboards[a], billboards[b])) continue;
      const FlipbookBillboard& A = billboards[a];
      const FlipbookBillboard& B = billboards[b];
      const glm::dvec2 pa(A.lateral, A.depth), pb(B.lateral, B.depth);
      const glm::dvec2 d = pb - pa;
      const double len = std::sqrt(d.x * d.x + d.y * d.y);
      if (len <= 0.0) continue;
      const glm::dvec2 u = d / len;
      // Counter-clockwise seen from above (up out of the page, lateral x, depth y toward the
      // viewer): tangent = (-r_y, r_x) / |r| at the midpoint r relative to the centroid.
      const glm::dvec2 r = 0.5 * (pa + pb) - centroid;
      const double rl = std::sqrt(r.x * r.x + r.y * r.y);
      const glm::dvec2 t = rl > 1e-12 ? glm::dvec2(-r.y, r.x) / rl : glm::dvec2(0.0);
      for (int step = 0; step < frame_count; ++step) {
        if (flipbook_frame(B.start_frame, B.increment, step + 1, frame_count) !=
            flipbook_frame(A.start_frame, A.increment, step, frame_count))
          continue;
        sum += u;
        tangential += u.x * t.x + u.y * t.y;
        ++transfers;
      }
    }
  }
  const double norm = static_cast<double>(frame_count) * static_cast<double>(billboards.size());
  const double sum_len = std::sqrt(sum.x * sum.x + sum.y * sum.y);
  m.march = sum_len / norm;
  m.circulation = std::fabs(tangential) / norm;
  m.transfers = static_cast<double>(transfers) / norm;
  if (sum_len > 1e-9) m.march_direction = glm::vec2(sum / sum_len);
  return m;
}

}  // namespace pyro
