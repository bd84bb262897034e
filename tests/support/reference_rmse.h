#pragma once
// The engine's first frame of a scene against the CPU reference of the same scene (the quality
// measurement's ground truth), as the RMSE over the frame at width x height, after checking that
// the reference exists and that every one of its pixels is finite.
#include <gtest/gtest.h>

#include <cmath>

#include "systems/runtime/quality/quality_settings.h"
#include "systems/runtime/quality_picker/quality_measurement.h"

namespace pyro::test {

inline double rmse_against_cpu_reference(const SceneDescription& scene, int width, int height) {
  const QualityGroundTruth truth(scene, width, height, {0});
  EXPECT_TRUE(truth.cpu_reference());
  for (float v : truth.image(0).rgb) EXPECT_TRUE(std::isfinite(v));
  return measure_rmse(scene, width, height, QualitySettings{}, truth);
}

}  // namespace pyro::test
