#pragma once
// pyro analyze six-way and six-way-relight: the six-way error (six_way_error.h) as a report, with
// its picture written as a PNG; a baked six-way frame (tools/bake) relit on the CPU by Unity's
// blend, over black, as a PNG.
#include <string>
#include <vector>

#include "tools/analyze/analysis_report.h"
#include "tools/analyze/six_way_error.h"

namespace pyro {

struct SixWayAnalysisOptions {
  std::string scene;  // "": content/scenes/six_way_smoke.json
  std::string image;  // "": no picture
  SixWayErrorOptions error;
};

AnalysisReport analyze_six_way(const SixWayAnalysisOptions& options);

struct SixWayRelightOptions {
  std::string folder;  // a bake-flipbook --six-way bake
  std::string image;
  int frame = 0;
  std::vector<float> light{1.0f, 1.0f, 1.0f};  // towards the light, in the camera's frame
};

// Writes the relit frame to `image` and returns the line that says so. UserError for a zero
// direction.
std::string relight_six_way_bake(const SixWayRelightOptions& options);

}  // namespace pyro
