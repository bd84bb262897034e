#include "engine/math/billboard_alignment.h"

#include <cmath>
#include <sstream>

namespace pyro {

namespace {

// s = sqrt(C_z^2 + C_x^2), the horizontal distance from the viewpoint to the centre
// (section 3.1, the norm in u*).
double horizontal_distance(const glm::dvec3& c) { return std::hypot(c.z, c.x); }

}  // namespace

glm::dvec2 project_to_viewplane(const glm::dvec3& p, double near) {
  // Eq 8: P* = (N P_x / -P_z, N P_y / -P_z).
  return {near * p.x / -p.z, near * p.y / -p.z};
}

glm::dvec3 viewplane_facing_edge(const glm::dvec3& centre, double radius) {
  // Section 3.1, above eq 9: E_perp = (C_x + r, C_y, C_z).
  return centre + glm::dvec3(radius, 0.0, 0.0);
}

glm::dvec3 viewpoint_facing_edge(const glm::dvec3& centre, double radius,
                                 const glm::dvec3& viewpoint) {
  // Section 3.1, above eq 10: E_bullet = C + r u*, u* = normalize((0,1,0) x (V - C)).
  const BillboardAxes<double> axes = viewpoint_facing_axes(
      centre, viewpoint, glm::dvec3(0.0, 1.0, 0.0), glm::dvec3(1.0, 0.0, 0.0));
  return centre + radius * axes.right;
}

ProjectionError projection_error(const glm::dvec3& centre, double radius, double near) {
  // Eqs 11 and 12 by their definitions: e = E_perp* - E_bullet*, each point projected by eq 8.
  const glm::dvec2 plane = project_to_viewplane(viewplane_facing_edge(centre, radius), near);
  const glm::dvec2 point = project_to_viewplane(viewpoint_facing_edge(centre, radius), near);
  return {plane.x - point.x, plane.y - point.y};
}

double paper_eq11_e_x(const glm::dvec3& c, double r, double n) {
  // Eq 11 as printed (it follows from the printed u* = (-C_z, 0, -C_x) / s, whose z sign is
  // wrong; see the header).
  const double s = horizontal_distance(c);
  return n * r * (c.x * c.x - c.z * s + r * c.x - c.z * c.z) / (-c.z * (-c.z * s + r * c.x));
}

double paper_eq12_e_y(const glm::dvec3& c, double r, double n) {
  // Eq 12 as printed (the printed u*'s sign slip, and a spurious factor s in the numerator).
  const double s = horizontal_distance(c);
  return n * r * c.x * c.y * s / (c.z * (c.z * s - r * c.x));
}

ProjectionError projection_error_paper(const glm::dvec3& centre, double radius, double near) {
  return {paper_eq11_e_x(centre, radius, near), paper_eq12_e_y(centre, radius, near)};
}

ProjectionError projection_error_closed_form(const glm::dvec3& c, double r, double n) {
  // Eq 9 minus eq 10 with the correct u* = (-C_z, 0, C_x) / s (docs/billboard_alignment.md):
  //   e_x = N r [C_x^2 + C_z s + r C_x + C_z^2] / (-C_z [C_z s + r C_x])   (corrected eq 11)
  //   e_y = N r C_x C_y / (C_z [-C_z s - r C_x])                            (corrected eq 12)
  const double s = horizontal_distance(c);
  const double e_x =
      n * r * (c.x * c.x + c.z * s + r * c.x + c.z * c.z) / (-c.z * (c.z * s + r * c.x));
  const double e_y = n * r * c.x * c.y / (c.z * (-c.z * s - r * c.x));
  return {e_x, e_y};
}

glm::dvec2 project_from_eye(const glm::dvec3& p, double near, double eye_x,
                            double zero_parallax_distance) {
  // Eq 8 from the eye at (eye_x, 0, 0) with the camera's axes, plus the off-axis window shift
  // that makes both eyes' windows coincide on the plane z = -Z0 (stereo_projection.h).
  const glm::dvec2 from_eye = project_to_viewplane(p - glm::dvec3(eye_x, 0.0, 0.0), near);
  return {from_eye.x + near * eye_x / zero_parallax_distance, from_eye.y};
}

ProjectionError projection_error_from_eye(const glm::dvec3& centre, double radius, double near,
                                          double eye_x, double zero_parallax_distance) {
  const glm::dvec3 eye(eye_x, 0.0, 0.0);
  const glm::dvec2 plane =
      project_from_eye(viewplane_facing_edge(centre, radius), near, eye_x, zero_parallax_distance);
  const glm::dvec2 point = project_from_eye(viewpoint_facing_edge(centre, radius, eye), near, eye_x,
                                            zero_parallax_distance);
  return {plane.x - point.x, plane.y - point.y};
}

ParallaxError parallax_error(const glm::dvec3& centre, double radius, double near,
                             double interocular) {
  // Section 3.3: right-eye projection error minus left-eye projection error. The window shift
  // cancels inside each error, so any zero-parallax distance gives the same result; N is used.
  const double half = 0.5 * interocular;
  const ProjectionError right = projection_error_from_eye(centre, radius, near, half, near);
  const ProjectionError left = projection_error_from_eye(centre, radius, near, -half, near);
  return {right.e_x - left.e_x, right.e_y - left.e_y};
}

std::string billboard_alignment_domain_problem(const glm::dvec3& centre, double radius, double near,
                                               double interocular) {
  std::ostringstream why;
  why.precision(9);
  if (!std::isfinite(centre.x) || !std::isfinite(centre.y) || !std::isfinite(centre.z) ||
      !std::isfinite(radius) || !std::isfinite(near) || !std::isfinite(interocular))
    return "every value must be a finite number";
  if (!(near > 0.0)) {
    why << "the viewplane distance N must be > 0, found " << near;
    return why.str();
  }
  if (!(radius >= 0.0)) {
    why << "the radius r must be >= 0, found " << radius;
    return why.str();
  }
  if (!(interocular >= 0.0)) {
    why << "the interocular distance I must be >= 0, found " << interocular;
    return why.str();
  }
  if (centre.z >= 0.0) {
    why << "the billboard centre is behind the camera (C_z = " << centre.z
        << " >= 0; the camera looks down -z)";
    return why.str();
  }
  if (centre.z == -near) {
    why << "the billboard centre is on the viewplane (C_z = -N = " << centre.z
        << "); it must lie beyond it, C_z < " << -near;
    return why.str();
  }
  if (centre.z > -near) {
    why << "the billboard centre lies between the viewpoint and the viewplane (C_z = " << centre.z
        << " > -N = " << -near << "); it must lie beyond it, C_z < " << -near;
    return why.str();
  }
  const double half = 0.5 * interocular;
  for (double eye_x : {0.0, -half, half}) {
    const glm::dvec3 e = viewpoint_facing_edge(centre, radius, glm::dvec3(eye_x, 0.0, 0.0));
    if (e.z >= -near) {
      why << "the right edge of the billboard turned to face the eye at x = " << eye_x
          << " reaches the viewplane (E_z = " << e.z << " >= -N = " << -near
          << "); move the centre farther away or make the radius smaller";
      return why.str();
    }
  }
  return {};
}

}  // namespace pyro
