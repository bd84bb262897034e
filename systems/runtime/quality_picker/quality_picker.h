#pragma once
// Quality from an error target: a scene that says "quality": {"max_rmse": E} gets the
// cheapest settings whose image RMSE against the ground truth (quality_measurement.h) is at most
// E, with a margin. Every candidate (layer scale 1 .. 1/8; footprint table 16, 32, 64 for
// Gaussian splats; 1 or 2 substeps per frame where emitters integrate dynamics) is rendered on
// this machine: its RMSE over a few frames and its time per frame. The pick is cached
// (quality_cache.h), so later runs of the same scene on the same machine measure nothing.
//
// Particle budgets are not searched: the scenes' particle counts are their content (a different
// count is a different random sample of the medium, an error the target would have to absorb).
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "systems/runtime/scene/scene_description.h"
#include "systems/runtime/quality/quality_settings.h"
#include "systems/runtime/scene_runtime/runtime_options.h"

namespace pyro {

struct QualitySearch {
  std::vector<int> frames = {0, 10, 20};  // frames whose error is measured (ascending)
  int timed_frames = 4;                   // frames timed per candidate (the fastest counts)
  double margin = 0.85;                   // a candidate qualifies at rmse <= margin * target
};

struct QualityPick {
  double max_rmse = 0.0;
  QualitySettings settings;
  double expected_rmse = 0.0;  // the pick's RMSE on the search frames
  double ms_per_frame = 0.0;
  bool met = false;  // false: nothing met the target; the most accurate candidate was picked
  QualitySettings defaults;    // full resolution, the scene's footprint, one step per frame
  double defaults_rmse = 0.0, defaults_ms_per_frame = 0.0;
  std::string ground_truth;
  bool from_cache = false;
  int measured_candidates = 0;  // 0 when read from the cache
  std::string cache_file, cache_key;
  nlohmann::json candidates = nlohmann::json::array();  // every candidate: settings, rmse, ms

  nlohmann::json to_json() const;
};

std::vector<QualitySettings> quality_candidates(const SceneDescription& scene);

// A pick read back (from the cache or an output folder's manifest) and checked: its settings are
// one of quality_candidates(scene), its numbers finite. Throws std::runtime_error saying why not.
QualityPick quality_pick_from_json(const nlohmann::json& j, const SceneDescription& scene);
QualitySettings full_resolution_defaults(const SceneDescription& scene);

// The scene as parsed (SceneDescription::content_digest) keys the cache with `renderer`, the size and the
// target. `max_rmse` > 0. Measures (and caches) when the cache has no entry; `use_cache` false
// measures and writes nothing. Notes (a measurement starting, a cache that cannot be written)
// go to `on_note`.
QualityPick pick_quality(const SceneDescription& scene, int width, int height, double max_rmse,
                         const std::string& renderer, bool use_cache = true,
                         const QualitySearch& search = {}, const NoteSink& on_note = {});

// The pick for the scene's own target (scene key quality.max_rmse) at the size it will run at
// with `options`, cached or measured; nothing when the scene sets no target. Its settings go
// into RuntimeOptions::quality, which resolve_scene applies.
std::optional<QualityPick> pick_scene_quality(const SceneDescription& scene,
                                              const RuntimeOptions& options,
                                              const std::string& renderer,
                                              const NoteSink& on_note = {});

// What a command's JSON summary reports of the pick it ran with: the target, the settings, the
// expected error, whether the target was met, the ground truth and whether the pick came from a
// cache (or an output folder's record).
nlohmann::json quality_pick_summary(const QualityPick& pick);

// One line describing the pick, for the user: the target, the settings, the expected error.
std::string quality_pick_note(const QualityPick& pick, const SceneDescription& scene);

// ", shadows map 64x32" (or ", shadows rays", ", shadows none") for a pick that chooses the
// shadows of lit media, else "".
std::string shadow_choice_text(const std::optional<ShadowChoice>& shadows);

}  // namespace pyro
