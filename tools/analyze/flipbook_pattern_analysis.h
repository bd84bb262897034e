#pragma once
// pyro analyze flipbook-pattern: how much flipbook frame patterns march or circle (Rose 2007,
// section 4.4; systems/flipbook_fire/flipbook_pattern.h), for the thesis' patterns or a scene's
// fires.
#include <string>

#include "tools/analyze/analysis_report.h"

namespace pyro {

struct FlipbookPatternOptions {
  std::string scene;  // "": the thesis' pairs and triplets
  int frames = 32;    // frames in the flipbook loop
};

AnalysisReport analyze_flipbook_pattern(const FlipbookPatternOptions& options);

}  // namespace pyro
