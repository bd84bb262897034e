// pyro analyze stereo [--interocular I] [--zero-parallax Z0] [--width W] [--height H] [--fov DEG]
//                     [--near N] [--far F] [--eye X Y Z] [--target X Y Z] [--samples K] [--json]
//
// Builds a mono camera frame and the two eye frames (make_eye_frame: parallel axes, off-axis
// frusta), projects a grid of points filling the view volume through both eyes and reports the
// largest vertical parallax and the largest departure of the horizontal parallax from its closed
// form (engine/math/stereo_parallax_analysis.h), with both eyes' matrices.
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "engine/core/user_error.h"
#include "engine/math/camera_math.h"
#include "engine/math/stereo_parallax_analysis.h"
#include "engine/math/stereo_projection.h"
#include "tools/pyro/commands.h"
#include "tools/pyro/stdout_text.h"

namespace pyro::cli {

namespace {

struct StereoArgs {
  float interocular = StereoParameters{}.interocular;
  float zero_parallax = StereoParameters{}.zero_parallax_distance;
  int width = 1024;
  int height = 768;
  float fov_y_deg = 45.0f;
  float near = 0.1f;
  float far = 200.0f;
  // The scenes' default camera (systems/runtime/scene/scene_description.h).
  std::vector<float> eye{0.0f, 1.5f, 8.0f};
  std::vector<float> target{0.0f, 1.5f, 0.0f};
  int samples = 21;
  bool json = false;
};

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

void print_matrix(const char* name, const glm::mat4& m) {
  for (int r = 0; r < 4; ++r)
    std::printf("    %-10s [% .9g % .9g % .9g % .9g]\n", r == 0 ? name : "", m[0][r] + 0.0f,
                m[1][r] + 0.0f, m[2][r] + 0.0f, m[3][r] + 0.0f);
}

void run_stereo(const StereoArgs& a) {
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

  const nlohmann::json out = {
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
  if (a.json) {
    write_stdout(out.dump() + "\n");
    return;
  }
  std::printf("stereo pair: %dx%d, fov %g deg, near %g, far %g, I = %g, Z0 = %g\n", a.width,
              a.height, a.fov_y_deg, a.near, a.far, a.interocular, a.zero_parallax);
  std::printf("%lld points from near to far, edge to edge of the frustum, through both eyes\n",
              r.points);
  std::printf("                                        double path     float path (renderer)\n");
  std::printf("  max vertical parallax (px)            %.3e       %.3e\n", r.max_vertical_parallax,
              r.max_vertical_parallax_float);
  std::printf("  max horizontal parallax error (px)    %.3e       %.3e\n",
              r.max_horizontal_parallax_error, r.max_horizontal_parallax_error_float);
  std::printf("  horizontal parallax range (px)        [%.4f, %.4f]\n", r.min_horizontal_parallax,
              r.max_horizontal_parallax);
  for (const auto& [name, f] : {std::pair{"left eye", &left}, std::pair{"right eye", &right}}) {
    std::printf("%s at (%.9g, %.9g, %.9g)\n", name, f->eye.x, f->eye.y, f->eye.z);
    print_matrix("view", f->view);
    print_matrix("projection", f->projection);
  }
}

}  // namespace

void add_analyze_stereo_command(CLI::App& analyze) {
  auto a = std::make_shared<StereoArgs>();
  CLI::App* cmd = analyze.add_subcommand(
      "stereo",
      "Vertical and horizontal parallax of the stereo eye frames over the whole view volume");
  cmd->add_option("--interocular", a->interocular, "Interocular distance I (default 0.065)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--zero-parallax", a->zero_parallax, "Zero-parallax distance Z0 (default 5)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--width", a->width, "Image width in pixels (default 1024)")
      ->check(CLI::Range(1, 65536));
  cmd->add_option("--height", a->height, "Image height in pixels (default 768)")
      ->check(CLI::Range(1, 65536));
  cmd->add_option("--fov", a->fov_y_deg, "Vertical field of view, degrees (default 45)")
      ->check(CLI::Range(0.001f, 179.0f));
  cmd->add_option("--near", a->near, "Near plane distance (default 0.1)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--far", a->far, "Far plane distance (default 200)")->check(CLI::PositiveNumber);
  cmd->add_option("--eye", a->eye, "Mono eye position X Y Z (default 0 1.5 8)")->expected(3);
  cmd->add_option("--target", a->target, "Point looked at X Y Z (default 0 1.5 0)")->expected(3);
  cmd->add_option("--samples", a->samples, "Grid points per axis (default 21)")
      ->check(CLI::Range(2, 401));
  cmd->add_flag("--json", a->json, "Print one JSON object");
  cmd->callback([a] { run_stereo(*a); });
}

}  // namespace pyro::cli
