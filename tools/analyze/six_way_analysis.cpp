#include "tools/analyze/six_way_analysis.h"

#include <cstdio>
#include <glm/geometric.hpp>

#include "engine/core/content_path.h"
#include "engine/core/format_text.h"
#include "engine/core/user_error.h"
#include "engine/io/output_gate.h"
#include "engine/io/png_file.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/scene_runtime/scene_inputs.h"
#include "tools/bake/six_way_folder.h"
#include "tools/bake/six_way_frame.h"

namespace pyro {

namespace {

std::string vector_text(const glm::vec3& v) {
  char text[64];
  std::snprintf(text, sizeof text, "(%+.3f, %+.3f, %+.3f)", v.x, v.y, v.z);
  return text;
}

void write_picture(const RgbImage& picture, const std::string& path) {
  std::vector<float> rgba(static_cast<size_t>(picture.width) * picture.height * 4, 1.0f);
  for (size_t p = 0; p < rgba.size() / 4; ++p)
    for (int c = 0; c < 3; ++c) rgba[4 * p + c] = picture.rgb[3 * p + c];
  write_png(path, picture.width, picture.height, 3,
            linear_rgba_to_srgb8(rgba, picture.width, picture.height));
}

}  // namespace

AnalysisReport analyze_six_way(const SixWayAnalysisOptions& a) {
  const std::string file = a.scene.empty() ? content_path("scenes/six_way_smoke.json") : a.scene;
  const SceneDescription scene = load_scene(file);
  OutputGate().reads(scene_inputs(file, scene)).writes_file(a.image, "--image").check();
  const SixWayErrorReport r = measure_six_way_error(scene, a.error);
  if (!a.image.empty()) write_picture(r.picture, a.image);
  nlohmann::json directions = nlohmann::json::array();
  for (const SixWayDirectionError& e : r.directions)
    directions.push_back(
        {{"towards_light", {e.towards_light.x, e.towards_light.y, e.towards_light.z}},
         {"rmse_six_way_engine", e.six_way_engine},
         {"rmse_six_way_reference_faces", e.six_way_reference},
         {"rmse_engine_lit", e.engine_lit},
         {"rmse_six_way_engine_vs_engine_lit", e.six_way_engine_vs_engine_lit}});
  AnalysisReport report;
  report.json = {{"scene", file},
                 {"frame", a.error.frame},
                 {"width", a.error.width},
                 {"height", a.error.height},
                 {"particles", r.particles},
                 {"directions", directions},
                 {"seconds", r.seconds}};
  report.text += format_text(
      "six-way relighting of %s, frame %d at %dx%d (%zu particles), RMSE against the CPU "
      "reference\n",
      file.c_str(), a.error.frame, a.error.width, a.error.height, r.particles);
  report.text += format_text("%-26s %14s %16s %12s %22s\n", "towards the light", "six-way (GL)",
                             "six-way (ref.)", "GL lit", "six-way (GL) vs GL lit");
  for (const SixWayDirectionError& e : r.directions)
    report.text += format_text("%-26s %14.4f %16.4f %12.4f %22.4f\n",
                               vector_text(e.towards_light).c_str(), e.six_way_engine,
                               e.six_way_reference, e.engine_lit, e.six_way_engine_vs_engine_lit);
  return report;
}

std::string relight_six_way_bake(const SixWayRelightOptions& a) {
  const glm::vec3 towards(a.light.at(0), a.light.at(1), a.light.at(2));
  if (glm::length(towards) < 1e-6f)
    throw UserError("", "--light", "expected a non-zero direction towards the light, found 0 0 0");
  OutputGate().reads(a.folder, "the six-way bake").writes_file(a.image, "--image").check();
  const SixWayFrame frame = unpack_six_way(read_six_way_frame(a.folder, a.frame));
  write_picture(relight_six_way(frame, towards), a.image);
  return format_text("relit frame %d of %s (%dx%d) for the light towards %s into %s\n", a.frame,
                     a.folder.c_str(), frame.width, frame.height,
                     vector_text(glm::normalize(towards)).c_str(), a.image.c_str());
}

}  // namespace pyro
