#include "systems/runtime/quality_picker/quality_picker.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <limits>
#include <optional>

#include "engine/core/user_error.h"
#include "engine/math/thick_particle.h"
#include "systems/runtime/quality/quality_cache.h"
#include "systems/runtime/quality_picker/quality_measurement.h"

namespace pyro {

namespace {

QualityPick pick_from_json_unchecked(const nlohmann::json& j) {
  QualityPick p;
  p.max_rmse = j.at("max_rmse").get<double>();
  p.settings = quality_settings_from_json(j.at("settings"));
  p.expected_rmse = j.at("expected_rmse").get<double>();
  p.ms_per_frame = j.at("ms_per_frame").get<double>();
  p.met = j.at("met").get<bool>();
  p.defaults = quality_settings_from_json(j.at("defaults").at("settings"));
  p.defaults_rmse = j.at("defaults").at("rmse").get<double>();
  p.defaults_ms_per_frame = j.at("defaults").at("ms_per_frame").get<double>();
  p.ground_truth = j.at("ground_truth").get<std::string>();
  p.candidates = j.at("candidates");
  return p;
}


}  // namespace

QualityPick quality_pick_from_json(const nlohmann::json& j, const SceneDescription& scene) {
  QualityPick p;
  try {
    p = pick_from_json_unchecked(j);
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(std::string("not a quality pick: ") + e.what());
  }
  // A pick is one of the candidates this scene would measure (a damaged or hand-edited entry,
  // e.g. a footprint of 0 or 1e9, would otherwise reach the renderer).
  bool candidate = false;
  for (const QualitySettings& q : quality_candidates(scene)) candidate = candidate || q == p.settings;
  if (!candidate)
    throw std::runtime_error("settings " + pyro::to_json(p.settings).dump() +
                             " are none of the scene's candidates");
  for (double v : {p.max_rmse, p.expected_rmse, p.ms_per_frame})
    if (!std::isfinite(v) || v < 0.0) throw std::runtime_error("a value that is not a finite number >= 0");
  return p;
}

nlohmann::json QualityPick::to_json() const {
  return {{"max_rmse", max_rmse},
          {"settings", pyro::to_json(settings)},
          {"expected_rmse", expected_rmse},
          {"ms_per_frame", ms_per_frame},
          {"met", met},
          {"defaults",
           {{"settings", pyro::to_json(defaults)}, {"rmse", defaults_rmse}, {"ms_per_frame", defaults_ms_per_frame}}},
          {"ground_truth", ground_truth},
          {"from_cache", from_cache},
          {"measured_candidates", measured_candidates},
          {"cache_file", cache_file},
          {"cache_key", cache_key},
          {"candidates", candidates}};
}

QualitySettings full_resolution_defaults(const SceneDescription& scene) {
  QualitySettings q;
  q.layer_scale = 1.0f;
  q.footprint_size = scene.footprint.size;
  q.substeps = 1;
  if (scene.shadows) q.shadows = shadow_choice(*scene.shadows);
  return q;
}

std::vector<QualitySettings> quality_candidates(const SceneDescription& scene) {
  std::vector<int> footprints = {scene.footprint.size};
  // The table shapes only Gaussian splats; its sampled error falls as 1/n^2 (README, Accuracy).
  if (gaussian_particles(scene)) footprints = {16, 32, 64};
  std::vector<int> substeps = {1};
  if (has_dynamics(scene)) substeps = {1, 2};
  // Lit media: the shadow methods of `pyro chart shadows` that the chart's Pareto fronts hold,
  // with the scene's own setting; for thick clouds also the finer map that `pyro chart shadows
  // --density` finds keeping the error down where the 64-texel one leaves it (docs/charts.md).
  std::vector<std::optional<ShadowChoice>> shadows = {std::nullopt};
  if (scene.shadows) {
    shadows = {ShadowChoice{ShadowMethod::none, 64, 32}, ShadowChoice{ShadowMethod::shadow_map, 32, 16},
               ShadowChoice{ShadowMethod::shadow_map, 64, 32}, ShadowChoice{ShadowMethod::rays, 64, 32}};
    if (std::any_of(scene.clouds.begin(), scene.clouds.end(),
                    [](const CloudDescription& c) { return thick_particle(c.density); }))
      shadows.push_back(ShadowChoice{ShadowMethod::shadow_map, 128, 64});
    const ShadowChoice own = shadow_choice(*scene.shadows);
    if (std::find(shadows.begin(), shadows.end(), own) == shadows.end()) shadows.push_back(own);
  }
  std::vector<QualitySettings> out;
  for (float scale : {1.0f, 0.5f, 0.25f, 0.125f})
    for (int n : footprints)
      for (int k : substeps)
        for (const std::optional<ShadowChoice>& s : shadows) out.push_back({scale, n, k, s});
  return out;
}

namespace {

// The cached pick under `key`, checked like any input: a damaged entry is dropped with a note and
// measured again.
std::optional<QualityPick> cached_pick(const std::string& path, const std::string& key,
                                       const SceneDescription& scene, const NoteSink& on_note) {
  const auto cached = read_quality_cache(path, key, on_note);
  if (!cached) return std::nullopt;
  try {
    QualityPick p = quality_pick_from_json(*cached, scene);
    p.from_cache = true;
    p.cache_file = path;
    p.cache_key = key;
    return p;
  } catch (const std::runtime_error& e) {
    if (on_note)
      on_note("quality: discarded a damaged entry of the cache \"" + path + "\" (" + e.what() +
              "); measuring again");
    return std::nullopt;
  }
}

// Adds candidate `q`, measured, to the pick, and takes it if it is the best so far: the fastest
// that qualifies, else (while none qualifies) the most accurate.
struct PickState {
  double best_ms = std::numeric_limits<double>::infinity();
  double best_rmse = std::numeric_limits<double>::infinity();
  bool have_met = false;
};

void consider(QualityPick& pick, PickState& state, const QualitySettings& q, double rmse,
              double ms, bool qualifies) {
  pick.candidates.push_back(
      {{"settings", to_json(q)}, {"rmse", rmse}, {"ms_per_frame", ms}, {"qualifies", qualifies}});
  if (q == pick.defaults) {
    pick.defaults_rmse = rmse;
    pick.defaults_ms_per_frame = ms;
  }
  if (qualifies && (!state.have_met || ms < state.best_ms)) {
    state.have_met = true;
    state.best_ms = ms;
    pick.settings = q, pick.expected_rmse = rmse, pick.ms_per_frame = ms;
  } else if (!state.have_met && rmse < state.best_rmse) {
    state.best_rmse = rmse;
    pick.settings = q, pick.expected_rmse = rmse, pick.ms_per_frame = ms;
  }
}

}  // namespace

QualityPick pick_quality(const SceneDescription& scene, int width, int height, double max_rmse,
                         const std::string& renderer, bool use_cache, const QualitySearch& search,
                         const NoteSink& on_note) {
  const std::string key =
      quality_cache_key(scene.content_digest, width, height, max_rmse, renderer);
  const std::string path = use_cache ? quality_cache_path() : std::string();
  if (use_cache)
    if (std::optional<QualityPick> p = cached_pick(path, key, scene, on_note)) return *p;

  const std::vector<QualitySettings> candidates = quality_candidates(scene);
  if (on_note)
    on_note("quality: measuring " + std::to_string(candidates.size()) + " candidate settings of " +
            scene.file + " against " +
            (gaussian_particles(scene) ? "the CPU reference" : "the converged GL render") + "...");
  const QualityGroundTruth truth(scene, width, height, search.frames);

  QualityPick pick;
  pick.max_rmse = max_rmse;
  pick.ground_truth = truth.description();
  pick.defaults = full_resolution_defaults(scene);
  pick.cache_file = path;
  pick.cache_key = key;
  PickState state;
  for (const QualitySettings& q : candidates) {
    const double rmse = measure_rmse(scene, width, height, q, truth);
    const double ms = measure_ms_per_frame(scene, width, height, q, search.timed_frames);
    ++pick.measured_candidates;
    consider(pick, state, q, rmse, ms, rmse <= search.margin * max_rmse);
  }
  pick.met = state.have_met;
  if (use_cache && !write_quality_cache(path, key, pick.to_json()) && on_note)
    on_note("quality: could not write the cache file \"" + path + "\"; the pick is not kept");
  return pick;
}

std::optional<QualityPick> pick_scene_quality(const SceneDescription& scene,
                                              const RuntimeOptions& options,
                                              const std::string& renderer, const NoteSink& on_note) {
  if (!scene.quality.given()) return std::nullopt;
  return pick_quality(scene, options.width_override > 0 ? options.width_override : scene.width,
                      options.height_override > 0 ? options.height_override : scene.height,
                      scene.quality.max_rmse, renderer, true, QualitySearch{}, on_note);
}

std::string shadow_choice_text(const std::optional<ShadowChoice>& s) {
  if (!s) return "";
  if (s->method != ShadowMethod::shadow_map) return ", shadows " + std::string(name_of(s->method));
  return ", shadows map " + std::to_string(s->map_size) + "x" + std::to_string(s->map_slices);
}

nlohmann::json quality_pick_summary(const QualityPick& pick) {
  return {{"max_rmse", pick.max_rmse},
          {"settings", to_json(pick.settings)},
          {"expected_rmse", pick.expected_rmse},
          {"met", pick.met},
          {"ground_truth", pick.ground_truth},
          {"from_cache", pick.from_cache}};
}

std::string quality_pick_note(const QualityPick& pick, const SceneDescription& scene) {
  char line[640];
  std::snprintf(line, sizeof line,
                "quality: max RMSE %g -> layer scale %g, footprint %d, %d step(s) per frame%s; "
                "expected RMSE %.4f against the %s (%s)%s",
                pick.max_rmse, pick.settings.layer_scale, pick.settings.footprint_size,
                pick.settings.substeps, shadow_choice_text(pick.settings.shadows).c_str(), pick.expected_rmse,
                gaussian_particles(scene) ? "CPU reference" : "converged GL render",
                pick.from_cache ? "cached" : "measured now",
                pick.met ? "" : "; no candidate met the target, the most accurate was picked");
  return line;
}

}  // namespace pyro
