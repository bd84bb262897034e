#pragma once
// pyro analyze stereo: builds a mono camera frame and the two eye frames (make_eye_frame:
// parallel axes, off-axis frusta), projects a grid of points filling the view volume through
// both eyes and reports the largest vertical parallax and the largest departure of the
// horizontal parallax from its closed form (engine/math/stereo_parallax_analysis.h), with both
// eyes' matrices.
#include <vector>

#include "engine/math/stereo_projection.h"
#include "tools/analyze/analysis_report.h"

namespace pyro {

struct StereoAnalysisOptions {
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
};

// Throws UserError for far not beyond near, a target at the eye or a vertical view.
AnalysisReport analyze_stereo(const StereoAnalysisOptions& options);

}  // namespace pyro
