#pragma once
// pyro analyze billboard-modes SCENE: the image difference between billboards facing the
// viewplane and facing the viewpoint (Johnson & McAllister 2005, section 3), per eye of a
// stereo pair, as RMSE of linear RGB, beside the time each mode takes per frame.
#include <string>

#include "engine/core/progress_sink.h"
#include "tools/analyze/analysis_report.h"

namespace pyro {

struct BillboardModesOptions {
  std::string scene;
  int width = 0, height = 0;  // 0: the scene's
  int frames = 5;             // timed frames per mode
  ProgressSink* progress = nullptr;
};

AnalysisReport analyze_billboard_modes(const BillboardModesOptions& options);

}  // namespace pyro
