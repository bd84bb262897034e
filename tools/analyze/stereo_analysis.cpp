#include "tools/analyze/stereo_analysis.h"

#include <glm/geometric.hpp>
#include <string>
#include <utility>

#include "engine/core/format_text.h"
#include "engine/core/user_error.h"
#include "engine/math/camera_math.h"
#include "engine/math/stereo_parallax_analysis.h"

namespace pyro {

namespace {

// Rows of a column-major glm matrix, for people to read.
nlohmann::json matrix_rows(const glm::mat4& m) {
  nlohmann::json rows = nlohmann::json::array();
  // + 0.0f turns -0 into 0.
  for (int r = 0; r < 4; ++r)
    rows.push_back({m[0][r] + 0.0f, m[1][r] + 0.0f, m[2][r] + 0.0f, m[3][r] + 0.0f});
  return rows;
}

nlohmann::json eye_json(const CameraFrame& f) {
  return {{"position", {f.eye.x, f.eye.y, f.eye.z}},
          {"view", matrix_rows(f.view)},
          {"projection", matrix_rows(f.projection)}};
}

std::string matrix_text(const char* name, const glm::mat4& m) {
  std::string text;
  for (int r = 0; r < 4; ++r)
    text += format_text("    %-10s [% .9g % .9g % .9g % .9g]\n", r == 0 ? name : "", m[0][r] + 0.0f,
                        m[1][r] + 0.0f, m[2][r] + 0.0f, m[3][r] + 0.0f);
  return text;
}

// The pair's text: the setting, the parallaxes, then each eye's matrices.
std::string stereo_text(const StereoAnalysisOptions& a, const StereoParallaxReport& r,
                        const CameraFrame& left, const CameraFrame& right) {
  std::string text;
  text += format_text("stereo pair: %dx%d, fov %g deg, near %g, far %g, I = %g, Z0 = %g\n", a.width,
                      a.height, a.fov_y_deg, a.near, a.far, a.interocular, a.zero_parallax);
  text += format_text(
      "%lld points from near to far, edge to edge of the frustum, through both eyes\n", r.points);
  text += format_text(
      "                                        double path     float path (renderer)\n");
  text += format_text("  max vertical parallax (px)            %.3e       %.3e\n",
                      r.max_vertical_parallax, r.max_vertical_parallax_float);
  text += format_text("  max horizontal parallax error (px)    %.3e       %.3e\n",
                      r.max_horizontal_parallax_error, r.max_horizontal_parallax_error_float);
  text += format_text("  horizontal parallax range (px)        [%.4f, %.4f]\n",
                      r.min_horizontal_parallax, r.max_horizontal_parallax);
  for (const auto& [name, f] : {std::pair{"left eye", &left}, std::pair{"right eye", &right}}) {
    text += format_text("%s at (%.9g, %.9g, %.9g)\n", name, f->eye.x, f->eye.y, f->eye.z);
    text += matrix_text("view", f->view);
    text += matrix_text("projection", f->projection);
  }
  return text;
}

}  // namespace

AnalysisReport analyze_stereo(const StereoAnalysisOptions& a) {
  if (!(a.far > a.near))
    throw UserError(
        "command line", "--far",
        "expected far > near (" + std::to_string(a.near) + "), found " + std::to_string(a.far));
  const glm::vec3 eye(a.eye[0], a.eye[1], a.eye[2]);
  const glm::vec3 target(a.target[0], a.target[1], a.target[2]);
  const glm::vec3 up(0.0f, 1.0f, 0.0f);
  const glm::vec3 view = target - eye;
  if (glm::length(view) == 0.0f)
    throw UserError("command line", "--target", "expected a target different from --eye");
  if (glm::length(glm::cross(glm::normalize(view), up)) < 1e-3f)
    throw UserError("command line", "--target",
                    "the view direction must not be vertical (the camera's up is +y)");
  const CameraFrame mono =
      make_camera_frame(eye, target, up, a.fov_y_deg, a.near, a.far, a.width, a.height);
  StereoParameters stereo;
  stereo.interocular = a.interocular;
  stereo.zero_parallax_distance = a.zero_parallax;
  const StereoParallaxReport r = analyze_stereo_parallax(mono, stereo, a.samples);
  const CameraFrame left = make_eye_frame(mono, stereo, Eye::left);
  const CameraFrame right = make_eye_frame(mono, stereo, Eye::right);

  AnalysisReport report;
  report.json = {
      {"width", a.width},
      {"height", a.height},
      {"fov_y_deg", a.fov_y_deg},
      {"near", a.near},
      {"far", a.far},
      {"eye", a.eye},
      {"target", a.target},
      {"interocular", a.interocular},
      {"zero_parallax_distance", a.zero_parallax},
      {"points", r.points},
      {"max_vertical_parallax", r.max_vertical_parallax},
      {"max_horizontal_parallax_error", r.max_horizontal_parallax_error},
      {"horizontal_parallax_range", {r.min_horizontal_parallax, r.max_horizontal_parallax}},
      {"max_vertical_parallax_float", r.max_vertical_parallax_float},
      {"max_horizontal_parallax_error_float", r.max_horizontal_parallax_error_float},
      {"left", eye_json(left)},
      {"right", eye_json(right)}};
  report.text = stereo_text(a, r, left, right);
  return report;
}

}  // namespace pyro
