// Billboard alignment error (Johnson & McAllister 2005, section 3, eqs 8-12): the errors from
// the geometry against an independent construction, the paper's printed closed forms against the
// geometry (and why they disagree), the corrected closed forms, the invariants the paper states,
// the parallax error's three equivalent definitions, and the viewpoint-facing axes.
//
// What the paper prints and what the geometry gives (docs/billboard_alignment.md):
//  - u*, under eq 9: printed (-C_z, 0, -C_x)/s; (0,1,0) x (V - C) is (-C_z, 0, C_x)/s. The printed
//    vector is not orthogonal to V - C: it turns the billboard the wrong way round.
//  - eq 11 is exact algebra from the printed u*: it equals the projection error of the mis-turned
//    billboard to rounding (PaperEq11IsTheErrorOfTheMisTurnedBillboard), so it has the wrong sign
//    and size wherever C_x != 0.
//  - eq 12 is s = sqrt(C_z^2 + C_x^2) times the error of the mis-turned billboard
//    (PaperEq12CarriesASpuriousFactorS): the sign slip plus an extra factor s, a length, so that
//    eq 12 is not invariant under scaling the scene (PaperEq12IsNotScaleInvariant).
//  - corrected: e_x = N r [C_x^2 + C_z s + r C_x + C_z^2] / (-C_z [C_z s + r C_x]),
//               e_y = N r C_x C_y / (C_z [-C_z s - r C_x]),
//    equal to the geometry to 1e-4 (relative above 1) everywhere in the domain
//    (CorrectedClosedFormsAgreeWithTheGeometryEverywhere).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include "engine/math/billboard_alignment.h"
#include "engine/core/rng.h"

namespace pyro {
namespace {

double uniform(Rng& rng, double lo, double hi) { return lo + (hi - lo) * rng.uniform(); }
double log_uniform(Rng& rng, double lo, double hi) {
  return std::exp(uniform(rng, std::log(lo), std::log(hi)));
}

struct Sample {
  glm::dvec3 c;
  double r;
  double n;
  double i;
};

// Random billboards anywhere in the analysed domain: depths from just beyond the viewplane to
// 1000 N, lateral offsets up to 4 times the depth (far outside any field of view), radii from
// 1e-4 to 10 N, viewplane distances from 0.01 to 10, interocular up to N.
std::vector<Sample> domain_samples(int count, uint64_t seed) {
  Rng rng(seed);
  std::vector<Sample> out;
  while (static_cast<int>(out.size()) < count) {
    Sample s;
    s.n = log_uniform(rng, 0.01, 10.0);
    s.r = s.n * log_uniform(rng, 1e-4, 10.0);
    s.i = s.n * uniform(rng, 0.0, 1.0);
    const double depth = s.n * (1.0 + log_uniform(rng, 1e-3, 1e3));
    s.c = {depth * uniform(rng, -4.0, 4.0), depth * uniform(rng, -4.0, 4.0), -depth};
    if (billboard_alignment_domain_problem(s.c, s.r, s.n, s.i).empty()) out.push_back(s);
  }
  return out;
}

// Agreement to `tol`, relative where |expected| > 1.
void expect_close(double actual, double expected, double tol, const Sample& s, const char* what) {
  EXPECT_LE(std::abs(actual - expected), tol * std::max(1.0, std::abs(expected)))
      << what << ": " << actual << " vs " << expected << " at C = (" << s.c.x << ", " << s.c.y
      << ", " << s.c.z << "), r = " << s.r << ", N = " << s.n;
}

// Independent construction: the ray from the viewpoint through P intersected with the plane
// z = -N (point (0,0,-N), normal (0,0,1)), by the ray-plane formula rather than eq 8.
glm::dvec2 ray_hits_viewplane(const glm::dvec3& p, double n) {
  const glm::dvec3 origin(0.0), direction = p - origin;
  const glm::dvec3 plane_point(0.0, 0.0, -n), plane_normal(0.0, 0.0, 1.0);
  const double t = glm::dot(plane_normal, plane_point - origin) / glm::dot(plane_normal, direction);
  const glm::dvec3 hit = origin + t * direction;
  EXPECT_NEAR(hit.z, -n, 1e-12 * n);
  return {hit.x, hit.y};
}

// Independent construction of the viewpoint-facing billboard's right edge: the viewplane-facing
// billboard (normal +z, right +x) turned about the vertical axis through C by the angle phi that
// points its normal at the viewpoint, phi = atan2(-C_x, -C_z).
glm::dvec3 turned_right_edge(const glm::dvec3& c, double r) {
  const double phi = std::atan2(-c.x, -c.z);
  const glm::dmat4 turn = glm::rotate(glm::dmat4(1.0), phi, glm::dvec3(0.0, 1.0, 0.0));
  const glm::dvec3 normal = glm::dvec3(turn * glm::dvec4(0.0, 0.0, 1.0, 0.0));
  EXPECT_NEAR(glm::dot(normal, glm::normalize(-c - glm::dvec3(0.0, -c.y, 0.0))), 1.0, 1e-12);
  return c + r * glm::dvec3(turn * glm::dvec4(1.0, 0.0, 0.0, 0.0));
}

// The viewpoint-facing E with the paper's printed u* = (-C_z, 0, -C_x) / s.
glm::dvec3 printed_u_star_edge(const glm::dvec3& c, double r) {
  const double s = std::hypot(c.z, c.x);
  return c + r * glm::dvec3(-c.z / s, 0.0, -c.x / s);
}

TEST(BillboardAlignment, ProjectionIsTheRayThroughThePointMeetingTheViewplane) {
  for (const Sample& s : domain_samples(2000, 11)) {
    const glm::dvec2 a = project_to_viewplane(s.c, s.n);
    const glm::dvec2 b = ray_hits_viewplane(s.c, s.n);
    expect_close(a.x, b.x, 1e-12, s, "x*");
    expect_close(a.y, b.y, 1e-12, s, "y*");
  }
}

TEST(BillboardAlignment, GeometricErrorsMatchAnIndependentConstruction) {
  for (const Sample& s : domain_samples(5000, 12)) {
    const glm::dvec2 plane = ray_hits_viewplane(s.c + glm::dvec3(s.r, 0.0, 0.0), s.n);
    const glm::dvec2 point = ray_hits_viewplane(turned_right_edge(s.c, s.r), s.n);
    const ProjectionError e = projection_error(s.c, s.r, s.n);
    expect_close(e.e_x, plane.x - point.x, 1e-9, s, "e_x");
    expect_close(e.e_y, plane.y - point.y, 1e-9, s, "e_y");
  }
}

TEST(BillboardAlignment, ViewpointFacingEdgeUsesTheRightAxisOfThePaper) {
  // u* = normalize((0,1,0) x (V - C)) = (-C_z, 0, C_x) / s: unit, horizontal, orthogonal to
  // V - C, pointing to the camera's right (u*_x > 0 in front of the camera); E_bullet = C + r u*.
  const glm::dvec3 v(0.0), y(0.0, 1.0, 0.0), x(1.0, 0.0, 0.0);
  for (const Sample& s : domain_samples(1000, 13)) {
    const glm::dvec3 u = viewpoint_facing_axes(s.c, v, y, x).right;
    const double hs = std::hypot(s.c.z, s.c.x);
    EXPECT_NEAR(glm::length(u), 1.0, 1e-15);
    EXPECT_EQ(u.y, 0.0);
    EXPECT_NEAR(glm::dot(u, v - s.c), 0.0, 1e-15 * glm::length(s.c));
    EXPECT_GT(u.x, 0.0);
    EXPECT_NEAR(u.x, -s.c.z / hs, 1e-15);
    EXPECT_NEAR(u.z, s.c.x / hs, 1e-15);
    const glm::dvec3 e = viewpoint_facing_edge(s.c, s.r);
    EXPECT_NEAR(glm::length(e - (s.c + s.r * u)), 0.0, 1e-15 * glm::length(s.c));
  }
}

TEST(BillboardAlignment, CorrectedClosedFormsAgreeWithTheGeometryEverywhere) {
  // Everywhere in front of the camera, i.e. in the domain: the billboard's centre and right
  // edges beyond the viewplane.
  for (const Sample& s : domain_samples(100000, 14)) {
    const ProjectionError g = projection_error(s.c, s.r, s.n);
    const ProjectionError c = projection_error_closed_form(s.c, s.r, s.n);
    expect_close(c.e_x, g.e_x, 1e-4, s, "corrected eq 11");
    expect_close(c.e_y, g.e_y, 1e-4, s, "corrected eq 12");
  }
  // And on a dense grid that includes the nearest billboards (edge just beyond the viewplane).
  const double n = 1.0, r = 0.4;
  for (double cz = -(n + r) - 1e-6; cz > -30.0; cz -= 0.0625) {
    for (double cx = -12.0; cx <= 12.0; cx += 0.25) {
      for (double cy : {-7.0, -1.0, 0.0, 0.5, 3.0}) {
        const Sample s{{cx, cy, cz}, r, n, 0.0};
        const ProjectionError g = projection_error(s.c, r, n);
        const ProjectionError c = projection_error_closed_form(s.c, r, n);
        expect_close(c.e_x, g.e_x, 1e-4, s, "corrected eq 11");
        expect_close(c.e_y, g.e_y, 1e-4, s, "corrected eq 12");
      }
    }
  }
}

TEST(BillboardAlignment, PaperEq11And12DisagreeWithTheGeometry) {
  // A sample point: C = (1, 1, -3), r = 0.5, N = 1. The geometry gives e_x = -0.018790 and
  // e_y = -0.018546; eq 11 prints +0.033158 and eq 12 +0.052774: wrong sign and size.
  const glm::dvec3 c(1.0, 1.0, -3.0);
  const ProjectionError g = projection_error(c, 0.5, 1.0);
  EXPECT_NEAR(g.e_x, -0.0187898417921103, 1e-12);
  EXPECT_NEAR(g.e_y, -0.0185456508458777, 1e-12);
  EXPECT_NEAR(paper_eq11_e_x(c, 0.5, 1.0), 0.0331575416080945, 1e-12);
  EXPECT_NEAR(paper_eq12_e_y(c, 0.5, 1.0), 0.0527741154501686, 1e-12);
  // Over the domain the printed forms are off by more than 1e-4 (relative above 1) at most
  // points with C_x != 0.
  int off_x = 0, off_y = 0, total = 0;
  for (const Sample& s : domain_samples(10000, 15)) {
    const ProjectionError e = projection_error(s.c, s.r, s.n);
    const ProjectionError p = projection_error_paper(s.c, s.r, s.n);
    off_x += std::abs(p.e_x - e.e_x) > 1e-4 * std::max(1.0, std::abs(e.e_x));
    off_y += std::abs(p.e_y - e.e_y) > 1e-4 * std::max(1.0, std::abs(e.e_y));
    ++total;
  }
  EXPECT_GT(off_x, total / 2);
  EXPECT_GT(off_y, total / 2);
  // They agree where the two turns coincide: on the z axis (C_x = 0) both vanish.
  const glm::dvec3 on_axis(0.0, 2.0, -4.0);
  EXPECT_NEAR(paper_eq11_e_x(on_axis, 0.5, 1.0), 0.0, 1e-15);
  EXPECT_NEAR(paper_eq12_e_y(on_axis, 0.5, 1.0), 0.0, 1e-15);
}

TEST(BillboardAlignment, PrintedUStarIsNotOrthogonalToTheViewDirection) {
  // The printed u* = (-C_z, 0, -C_x)/s has u* . (V - C) = 2 C_x C_z / s, not 0.
  const glm::dvec3 c(1.5, 0.3, -4.0);
  const double s = std::hypot(c.z, c.x);
  const glm::dvec3 printed(-c.z / s, 0.0, -c.x / s);
  EXPECT_NEAR(glm::dot(printed, -c), 2.0 * c.x * c.z / s, 1e-12);
  EXPECT_GT(std::abs(glm::dot(printed, -c)), 1.0);
  const glm::dvec3 corrected = glm::normalize(glm::cross(glm::dvec3(0.0, 1.0, 0.0), -c));
  EXPECT_NEAR(glm::dot(corrected, -c), 0.0, 1e-12);
}

TEST(BillboardAlignment, PaperEq11IsTheErrorOfTheMisTurnedBillboard) {
  // Eq 11 is correct algebra from the printed u*: it is E_perp* - E* with E = C + r u*_printed.
  for (const Sample& s : domain_samples(20000, 16)) {
    const glm::dvec3 e = printed_u_star_edge(s.c, s.r);
    if (e.z >= -s.n) continue;  // the mis-turned edge can reach the viewplane
    const double mis_turned = project_to_viewplane(viewplane_facing_edge(s.c, s.r), s.n).x -
                              project_to_viewplane(e, s.n).x;
    expect_close(paper_eq11_e_x(s.c, s.r, s.n), mis_turned, 1e-6, s, "eq 11 vs mis-turned");
  }
}

TEST(BillboardAlignment, PaperEq12CarriesASpuriousFactorS) {
  // Eq 12 = s * (the vertical error of the mis-turned billboard), s = sqrt(C_z^2 + C_x^2).
  for (const Sample& s : domain_samples(20000, 17)) {
    const glm::dvec3 e = printed_u_star_edge(s.c, s.r);
    if (e.z >= -s.n) continue;
    const double mis_turned = project_to_viewplane(viewplane_facing_edge(s.c, s.r), s.n).y -
                              project_to_viewplane(e, s.n).y;
    const double hs = std::hypot(s.c.z, s.c.x);
    expect_close(paper_eq12_e_y(s.c, s.r, s.n) / hs, mis_turned, 1e-6, s, "eq 12 / s");
  }
}

TEST(BillboardAlignment, PaperEq12IsNotScaleInvariant) {
  // Scaling the billboard's position and radius by k (N fixed) leaves every projection error
  // unchanged: projections are ratios of lengths. Eq 12 grows by k: it is a length squared.
  const glm::dvec3 c(1.2, -0.7, -3.5);
  const double r = 0.4, n = 1.0;
  for (double k : {0.5, 2.0, 10.0}) {
    const ProjectionError g1 = projection_error(c, r, n), gk = projection_error(k * c, k * r, n);
    EXPECT_NEAR(gk.e_x, g1.e_x, 1e-14);
    EXPECT_NEAR(gk.e_y, g1.e_y, 1e-14);
    EXPECT_NEAR(paper_eq11_e_x(k * c, k * r, n), paper_eq11_e_x(c, r, n), 1e-14);
    EXPECT_NEAR(paper_eq12_e_y(k * c, k * r, n), k * paper_eq12_e_y(c, r, n), 1e-12);
  }
}

TEST(BillboardAlignment, VerticalErrorVanishesOnTheAxes) {
  // Section 3.1.2: e_y = 0 when C_x = 0 (E_perp = E_bullet) or C_y = 0 (E_perp, E_bullet and V
  // in the xz plane). And e_x = 0 when C_x = 0.
  for (const Sample& s : domain_samples(2000, 18)) {
    const glm::dvec3 cx0(0.0, s.c.y, s.c.z), cy0(s.c.x, 0.0, s.c.z);
    const ProjectionError a = projection_error(cx0, s.r, s.n);
    EXPECT_NEAR(a.e_y, 0.0, 1e-15 * std::max(1.0, s.n * std::abs(s.c.y / s.c.z)));
    EXPECT_NEAR(a.e_x, 0.0, 1e-15 * std::max(1.0, s.n * s.r / -s.c.z));
    EXPECT_EQ(projection_error(cy0, s.r, s.n).e_y, 0.0);
    EXPECT_EQ(projection_error_closed_form(cx0, s.r, s.n).e_y, 0.0);
    EXPECT_EQ(projection_error_closed_form(cy0, s.r, s.n).e_y, 0.0);
  }
}

TEST(BillboardAlignment, ErrorsVanishFarAway) {
  // As C_z -> -inf the errors fall as 1/|C_z|^3, from the corrected forms:
  //   e_x |C_z|^3 -> -N r (C_x^2 / 2 + r C_x),   e_y |C_z|^3 -> -N r C_x C_y.
  const double r = 0.4, n = 1.0;
  for (const glm::dvec2 xy : {glm::dvec2(2.0, 1.0), glm::dvec2(-3.0, 0.5), glm::dvec2(0.7, -4.0)}) {
    double last_x = INFINITY, last_y = INFINITY;
    for (double d = 10.0; d <= 1e6; d *= 10.0) {
      const ProjectionError e = projection_error({xy.x, xy.y, -d}, r, n);
      EXPECT_LT(std::abs(e.e_x), last_x);
      EXPECT_LT(std::abs(e.e_y), last_y);
      last_x = std::abs(e.e_x);
      last_y = std::abs(e.e_y);
    }
    EXPECT_LT(last_x, 1e-15);
    EXPECT_LT(last_y, 1e-15);
    const double d = 1e4;
    const ProjectionError e = projection_error({xy.x, xy.y, -d}, r, n);
    EXPECT_NEAR(e.e_x * d * d * d, -n * r * (xy.x * xy.x / 2.0 + r * xy.x),
                1e-3 * n * r * (xy.x * xy.x / 2.0 + r * std::abs(xy.x)));
    EXPECT_NEAR(e.e_y * d * d * d, -n * r * xy.x * xy.y, 1e-3 * n * r * std::abs(xy.x * xy.y));
  }
}

TEST(BillboardAlignment, ErrorsVanishWithTheRadius) {
  // First order in r (the Jacobian of eq 8 applied to E_perp - E_bullet = r ((1,0,0) - u*)):
  //   e_x / r -> N (d - s) / d^2,   e_y / r -> -N C_x C_y / (d^2 s),   d = -C_z.
  for (const Sample& s : domain_samples(500, 19)) {
    const double d = -s.c.z, hs = std::hypot(s.c.z, s.c.x);
    const double slope_x = s.n * (d - hs) / (d * d), slope_y = -s.n * s.c.x * s.c.y / (d * d * hs);
    double last = INFINITY;
    for (double r : {1e-2, 1e-4, 1e-6}) {
      const double radius = r * s.n;
      const ProjectionError e = projection_error(s.c, radius, s.n);
      const double size = std::hypot(e.e_x, e.e_y);
      EXPECT_LE(size, last);
      last = size;
      if (r == 1e-6) {
        EXPECT_NEAR(e.e_x / radius, slope_x, 1e-4 * std::max(1.0, std::abs(slope_x)));
        EXPECT_NEAR(e.e_y / radius, slope_y, 1e-4 * std::max(1.0, std::abs(slope_y)));
      }
    }
    const ProjectionError zero = projection_error(s.c, 0.0, s.n);
    EXPECT_EQ(zero.e_x, 0.0);
    EXPECT_EQ(zero.e_y, 0.0);
  }
}

TEST(BillboardAlignment, ParallaxErrorDefinitionsAgree) {
  // (a) right-eye error minus left-eye error, billboards turned to each eye, each eye's off-axis
  // projection (parallax_error); (b) the parallax of E on the viewplane-facing billboard minus
  // the parallax of E on the viewpoint-facing billboards; (c) the paper's translated surfaces,
  // e(C - (I/2,0,0)) - e(C + (I/2,0,0)).
  for (const Sample& s : domain_samples(5000, 20)) {
    const ParallaxError a = parallax_error(s.c, s.r, s.n, s.i);
    const double half = 0.5 * s.i, z0 = s.n * 5.0;
    const glm::dvec3 right_eye(half, 0.0, 0.0), left_eye(-half, 0.0, 0.0);
    const glm::dvec3 e_perp = viewplane_facing_edge(s.c, s.r);
    const glm::dvec2 plane_parallax =
        project_from_eye(e_perp, s.n, half, z0) - project_from_eye(e_perp, s.n, -half, z0);
    const glm::dvec2 point_parallax =
        project_from_eye(viewpoint_facing_edge(s.c, s.r, right_eye), s.n, half, z0) -
        project_from_eye(viewpoint_facing_edge(s.c, s.r, left_eye), s.n, -half, z0);
    const ParallaxError c = parallax_error_from_translated_surfaces(
        s.c, s.i, [&](const glm::dvec3& at) { return projection_error(at, s.r, s.n); });
    expect_close(a.horizontal, plane_parallax.x - point_parallax.x, 1e-9, s,
                 "(a) vs (b) horizontal");
    expect_close(a.vertical, plane_parallax.y - point_parallax.y, 1e-9, s, "(a) vs (b) vertical");
    expect_close(a.horizontal, c.horizontal, 1e-9, s, "(a) vs (c) horizontal");
    expect_close(a.vertical, c.vertical, 1e-9, s, "(a) vs (c) vertical");
  }
}

TEST(BillboardAlignment, ParallaxErrorVanishesWithoutInterocularAndVerticallyOnTheXzPlane) {
  for (const Sample& s : domain_samples(2000, 21)) {
    const ParallaxError none = parallax_error(s.c, s.r, s.n, 0.0);
    EXPECT_EQ(none.horizontal, 0.0);
    EXPECT_EQ(none.vertical, 0.0);
    EXPECT_EQ(parallax_error({s.c.x, 0.0, s.c.z}, s.r, s.n, s.i).vertical, 0.0);
  }
  // Section 3.3: little parallax error for distant billboards.
  double last = INFINITY;
  for (double d = 2.0; d < 1e4; d *= 2.0) {
    const double h = std::abs(parallax_error({1.5, 0.8, -d}, 0.4, 1.0, 0.065).horizontal);
    EXPECT_LT(h, last);
    last = h;
  }
  EXPECT_LT(last, 1e-12);
}

TEST(BillboardAlignment, DomainRefusesPointsBehindOrOnTheViewplane) {
  EXPECT_TRUE(billboard_alignment_domain_problem({1, 1, -3}, 0.5, 1.0, 0.065).empty());
  EXPECT_NE(billboard_alignment_domain_problem({1, 1, 2}, 0.5, 1.0, 0.0).find("behind the camera"),
            std::string::npos);
  EXPECT_NE(billboard_alignment_domain_problem({1, 1, -1}, 0.5, 1.0, 0.0).find("on the viewplane"),
            std::string::npos);
  EXPECT_NE(billboard_alignment_domain_problem({1, 1, -0.5}, 0.1, 1.0, 0.0).find("between"),
            std::string::npos);
  // Centre beyond the viewplane, but the turned right edge reaches it.
  EXPECT_NE(billboard_alignment_domain_problem({3, 0, -1.2}, 0.5, 1.0, 0.0).find("reaches"),
            std::string::npos);
  EXPECT_FALSE(billboard_alignment_domain_problem({0, 0, -3}, 0.5, 0.0, 0.0).empty());
  EXPECT_FALSE(billboard_alignment_domain_problem({0, 0, -3}, -0.5, 1.0, 0.0).empty());
  EXPECT_FALSE(billboard_alignment_domain_problem({0, 0, -3}, 0.5, 1.0, -1.0).empty());
  EXPECT_FALSE(billboard_alignment_domain_problem({NAN, 0, -3}, 0.5, 1.0, 0.0).empty());
}

// --- The viewpoint-facing axes (the renderer's single source of truth) ---

TEST(ViewpointFacingAxes, OrthonormalFacingTheEyeWithAHorizontalRightAxis) {
  Rng rng(22);
  const glm::dvec3 up(0.0, 1.0, 0.0), right(1.0, 0.0, 0.0);
  for (int k = 0; k < 5000; ++k) {
    const glm::dvec3 c(uniform(rng, -50, 50), uniform(rng, -50, 50), uniform(rng, -50, 50));
    const glm::dvec3 eye(uniform(rng, -5, 5), uniform(rng, -5, 5), uniform(rng, -5, 5));
    const BillboardAxes<double> a = viewpoint_facing_axes(c, eye, up, right);
    const glm::dvec3 n = glm::normalize(eye - c);
    EXPECT_NEAR(glm::length(a.right), 1.0, 1e-12);
    EXPECT_NEAR(glm::length(a.up), 1.0, 1e-12);
    EXPECT_NEAR(glm::dot(a.right, a.up), 0.0, 1e-12);
    EXPECT_NEAR(glm::dot(a.right, n), 0.0, 1e-12);
    EXPECT_NEAR(glm::dot(a.up, n), 0.0, 1e-12);
    EXPECT_NEAR(glm::dot(a.right, up), 0.0, 1e-12);                       // horizontal
    EXPECT_GE(glm::dot(a.up, up), 0.0);                                   // up stays up
    EXPECT_NEAR(glm::length(glm::cross(a.right, a.up) - n), 0.0, 1e-12);  // front face to eye
  }
}

TEST(ViewpointFacingAxes, OnTheViewAxisTheyAreTheCameraAxes) {
  const BillboardAxes<double> a = viewpoint_facing_axes(glm::dvec3(0, 0, -7), glm::dvec3(0),
                                                        glm::dvec3(0, 1, 0), glm::dvec3(1, 0, 0));
  EXPECT_NEAR(glm::length(a.right - glm::dvec3(1, 0, 0)), 0.0, 1e-15);
  EXPECT_NEAR(glm::length(a.up - glm::dvec3(0, 1, 0)), 0.0, 1e-15);
}

TEST(ViewpointFacingAxes, StraightAboveTheEyeFallsBackToTheCameraRight) {
  const glm::dvec3 c(0, 10, 0), eye(0, 0, 0);
  const BillboardAxes<double> a =
      viewpoint_facing_axes(c, eye, glm::dvec3(0, 1, 0), glm::dvec3(1, 0, 0));
  EXPECT_NEAR(glm::length(a.right - glm::dvec3(1, 0, 0)), 0.0, 1e-15);
  EXPECT_NEAR(glm::length(glm::cross(a.right, a.up) - glm::normalize(eye - c)), 0.0, 1e-15);
}

TEST(ViewpointFacingAxes, FollowTheCameraWhenTheWorldRotates) {
  // In world space the renderer passes the camera's up and right: the axes of a rotated scene
  // are the rotated axes, and the float version (for the GPU side) agrees with the double one.
  Rng rng(23);
  for (int k = 0; k < 200; ++k) {
    const glm::dvec3 axis =
        glm::normalize(glm::dvec3(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)) +
                       glm::dvec3(0.0, 0.0, 1e-3));
    const glm::dmat3 rot(glm::rotate(glm::dmat4(1.0), uniform(rng, -3, 3), axis));
    const glm::dvec3 c(uniform(rng, -5, 5), uniform(rng, -5, 5), uniform(rng, -30, -2));
    const glm::dvec3 eye(uniform(rng, -0.1, 0.1), 0.0, 0.0);
    const BillboardAxes<double> a =
        viewpoint_facing_axes(c, eye, glm::dvec3(0, 1, 0), glm::dvec3(1, 0, 0));
    const BillboardAxes<double> b = viewpoint_facing_axes(
        rot * c, rot * eye, rot * glm::dvec3(0, 1, 0), rot * glm::dvec3(1, 0, 0));
    EXPECT_NEAR(glm::length(b.right - rot * a.right), 0.0, 1e-12);
    EXPECT_NEAR(glm::length(b.up - rot * a.up), 0.0, 1e-12);
    const BillboardAxes<float> f = viewpoint_facing_axes(glm::vec3(rot * c), glm::vec3(rot * eye),
                                                         glm::vec3(rot * glm::dvec3(0, 1, 0)),
                                                         glm::vec3(rot * glm::dvec3(1, 0, 0)));
    EXPECT_NEAR(glm::length(glm::dvec3(f.right) - b.right), 0.0, 1e-5);
    EXPECT_NEAR(glm::length(glm::dvec3(f.up) - b.up), 0.0, 1e-5);
  }
}

}  // namespace
}  // namespace pyro
