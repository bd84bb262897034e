#include "tools/analyze/flipbook_pattern_analysis.h"

#include <utility>
#include <vector>

#include "engine/core/format_text.h"
#include "systems/flipbook_fire/flipbook_layout.h"
#include "systems/flipbook_fire/flipbook_pattern.h"
#include "systems/runtime/scene/scene_loader.h"

namespace pyro {

namespace {

nlohmann::json motion_json(const std::string& name, const FlipbookFire& fire, int frames) {
  const PatternMotion m = measure_pattern_motion(expand_flipbook_groups(fire), frames);
  nlohmann::json groups = nlohmann::json::array();
  for (const FlipbookGroup& g : fire.groups)
    groups.push_back({{"rows", g.rows},
                      {"columns", g.columns},
                      {"start_frames", g.start_frames},
                      {"row_start_step", g.row_start_step},
                      {"increments", g.increments}});
  return {{"name", name},
          {"groups", groups},
          {"march", m.march},
          {"circulation", m.circulation},
          {"transfers", m.transfers},
          {"march_direction", {m.march_direction.x, m.march_direction.y}}};
}

// The thesis' patterns, or the scene's fires.
nlohmann::json measure_patterns(const FlipbookPatternOptions& a) {
  nlohmann::json patterns = nlohmann::json::array();
  if (a.scene.empty()) {
    // The thesis' three overlapped pairs (section 4.4) with its three increment patterns, and
    // its triplets (section 4.5: l = -2, m = 1, n = -2).
    const std::vector<std::pair<std::string, std::vector<int>>> pairs = {
        {"pairs +1 +1 (moves away, thesis)", {1, 1}},
        {"pairs +1 -1 (circles, thesis)", {1, -1}},
        {"pairs m=1 n=-2 (thesis' choice)", {1, -2}}};
    for (const auto& [name, increments] : pairs) {
      FlipbookFire fire;
      fire.groups.emplace_back().increments = increments;
      patterns.push_back(motion_json(name, fire, a.frames));
    }
    FlipbookFire triplets;
    FlipbookGroup& g = triplets.groups.emplace_back();
    g.columns = 3;
    g.column_depths = {0.0f, -0.1f, 0.0f};
    g.start_frames = {2, 10, 18};
    g.increments = {-2, 1, -2};
    patterns.push_back(
        motion_json("triplets l=-2 m=1 n=-2 (thesis' additive scaling)", triplets, a.frames));
    g.increments = {1, 1, 1};
    patterns.push_back(motion_json("triplets +1 +1 +1", triplets, a.frames));
  } else {
    const SceneDescription scene = load_scene(a.scene);
    for (size_t i = 0; i < scene.fires.size(); ++i)
      patterns.push_back(motion_json(
          scene.fires[i].name.empty() ? "/fires/" + std::to_string(i) : scene.fires[i].name,
          scene.fires[i], a.frames));
  }
  return patterns;
}

}  // namespace

AnalysisReport analyze_flipbook_pattern(const FlipbookPatternOptions& a) {
  const nlohmann::json patterns = measure_patterns(a);
  AnalysisReport r;
  r.json = {{"frames", a.frames}, {"patterns", patterns}};
  r.text += format_text("apparent motion of flipbook frame patterns over a loop of %d frames\n",
                        a.frames);
  r.text += format_text(
      "(transfers of a frame to a neighbouring billboard one step later, per billboard per "
      "step)\n");
  r.text += format_text("%-52s %8s %12s %10s\n", "pattern", "march", "circulation", "transfers");
  for (const nlohmann::json& p : patterns)
    r.text += format_text("%-52s %8.4f %12.4f %10.4f\n", p["name"].get<std::string>().c_str(),
                          p["march"].get<double>(), p["circulation"].get<double>(),
                          p["transfers"].get<double>());
  return r;
}

}  // namespace pyro
