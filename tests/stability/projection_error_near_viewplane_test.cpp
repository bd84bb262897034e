// Stability: the billboard projection error (Johnson & McAllister 2005, section 3) as a particle
// approaches the viewplane. The engine's closed forms (engine/math/billboard_alignment.h, the
// corrected eqs 11 and 12) follow the geometry all the way in; the paper's printed eqs 11 and 12,
// the naive method, drift away from it (sign slip in u*, spurious factor in eq 12), and further
// the closer the particle comes.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/vec3.hpp>

#include "engine/math/billboard_alignment.h"

namespace pyro {
namespace {

TEST(StabilityProjectionError, CorrectedFormsFollowTheGeometryToTheViewplanePaperFormsDoNot) {
  const double r = 0.4, near = 1.0;
  double worst_paper = 0.0;
  // The nearest edge reaches the viewplane when C_z = -(N + r): approach it geometrically.
  for (double gap : {8.0, 2.0, 0.5, 0.1, 0.02, 1e-3}) {
    const glm::dvec3 c(1.0, 0.8, -(near + r + gap));
    ASSERT_TRUE(billboard_alignment_domain_problem(c, r, near, 0.0).empty()) << gap;
    const ProjectionError geometry = projection_error(c, r, near);
    const ProjectionError closed = projection_error_closed_form(c, r, near);
    const ProjectionError paper = projection_error_paper(c, r, near);
    ASSERT_TRUE(std::isfinite(geometry.e_x) && std::isfinite(geometry.e_y)) << gap;
    const double scale = std::max(std::abs(geometry.e_x), std::abs(geometry.e_y));
    EXPECT_LE(std::abs(closed.e_x - geometry.e_x), 1e-4 * scale + 1e-12) << gap;
    EXPECT_LE(std::abs(closed.e_y - geometry.e_y), 1e-4 * scale + 1e-12) << gap;
    worst_paper = std::max(worst_paper, std::abs(paper.e_x - geometry.e_x) / scale);
  }
  EXPECT_GT(worst_paper, 0.5) << "the printed eq 11 should be far from the geometry";
}

}  // namespace
}  // namespace pyro
