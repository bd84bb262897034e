// pyro chart shadows: the light phase's shadow methods (systems/shadowing) on lit scenes, each
// frame against the CPU reference with exact shadows (systems/runtime/reference/lit_particle_reference.h).
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "components/anisotropic_cloud.h"
#include "components/frame_image.h"
#include "engine/core/content_path.h"
#include "tools/bench/frame_timing.h"
#include "tools/charts/charts.h"
#include "systems/runtime/open_scene/open_scene.h"
#include "systems/runtime/quality_picker/quality_measurement.h"
#include "systems/runtime/reference/world_snapshot.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"

namespace pyro {

namespace {

// The settings charted: lit without shadows, the exact rays, and the map at each size (slices
// half its texels across); the shadowed ones with the splats' sunlight per fragment and at the
// vertices (without shadows the two are the same light; scenes without isotropic splats skip
// the latter, whose frames would be the same).
std::vector<ShadowSettings> shadow_candidates(const std::vector<int>& map_sizes) {
  std::vector<ShadowSettings> out;
  ShadowSettings s;
  s.method = ShadowMethod::none;
  out.push_back(s);
  s.method = ShadowMethod::rays;
  out.push_back(s);
  for (int size : map_sizes) {
    s.method = ShadowMethod::shadow_map;
    s.map_size = size;
    s.map_slices = std::max(4, size / 2);
    out.push_back(s);
  }
  for (size_t k = 1, shadowed = out.size(); k < shadowed; ++k) {
    s = out[k];
    s.splat_sunlight = SplatSunlight::vertices;
    out.push_back(s);
  }
  return out;
}

std::string setting_name(const ShadowSettings& s) {
  const std::string sunlight = s.splat_sunlight == SplatSunlight::vertices ? " sunlight at vertices" : "";
  if (s.method != ShadowMethod::shadow_map) return std::string(name_of(s.method)) + sunlight;
  return "map " + std::to_string(s.map_size) + "x" + std::to_string(s.map_slices) + sunlight;
}

// Milliseconds a frame of the light phase's shadow systems, the mean over `frames` frames.
double shadow_ms_per_frame(const SceneDescription& scene, const RuntimeOptions& options, int frames) {
  // as written (no quality pick): times the shadow setting the chart sets
  const std::unique_ptr<SceneRuntime> runtime = open_runtime(scene, options);
  for (int f = 0; f < frames; ++f) runtime->draw_frame(f);
  double ms = 0.0;
  for (const ecs::SystemStats& s : runtime->schedule().stats())
    if (s.name == "shadow_map" || s.name == "shadow_rays") ms += s.total_ms;
  return ms / frames;
}

// The world's Gaussians, isotropic and anisotropic.
std::size_t particle_count(ecs::World& world) {
  std::size_t n = gather_particles(world).size();
  world.each<const AnisotropicCloud>([&](const AnisotropicCloud& c) { n += c.particles.size(); });
  return n;
}

}  // namespace

ChartTable chart_shadows(const ShadowsChartOptions& o) {
  std::vector<std::string> scenes = o.scenes;
  if (scenes.empty())
    for (const char* s : {"scenes/clouds.json", "scenes/fog.json", "scenes/cloud_fitted.json"})
      scenes.push_back(content_path(s));
  ChartTable t;
  t.name = "shadows";
  t.title = "Shadow methods against the reference with exact shadows (" + std::to_string(o.width) +
            "x" + std::to_string(o.height) + ")";
  t.x_label = "ms per frame (mono)";
  t.y_label = "RMSE (linear RGB) against the CPU reference with exact shadows";
  t.ground_truth =
      "single scattering of the sun with its transmittance exact at every point of every ray "
      "(systems/runtime/reference/lit_particle_reference.h), over the GL opaque scene whose sunlight keeps "
      "exp(-tau) of the exact optical depth";
  t.notes = {"none: lit by the sun without shadows; rays: exact transmittance at each particle "
             "(engine/math/shadow_ray_index.h); map SxK: opacity shadow map of S texels across and K "
             "slices (Kim & Neumann 2001), which the ground reads under every method; sunlight at "
             "vertices: the splats' sunlight a plane across each billboard (content/shaders/"
             "splat_sunlight.glsl), otherwise each fragment's own",
             "shadow_ms: the light phase's shadow systems alone, per frame"};
  t.extra_columns = {"shadow_ms", "particles"};
  for (const std::string& file : scenes) {
    SceneDescription scene = load_scene(file);
    prepare_scene_run(scene);  // before the measurement's and the timed runtimes open it
    const std::string stem = std::filesystem::path(file).stem().string();
    // The scene's own lobe and octaves (if lit as shipped), under every method.
    const ShadowSettings shipped = scene.shadows.value_or(ShadowSettings{});
    scene.shadows = shipped;
    const RgbImage reference = particle_scene_references(scene, o.width, o.height, {0}).at(0);
    std::optional<bool> splats;  // whether the scene has isotropic splats, whose sunlight may be at the vertices
    for (ShadowSettings s : shadow_candidates(o.map_sizes)) {
      if (s.splat_sunlight == SplatSunlight::vertices && splats == false) continue;  // the same frames again
      s.scattering = shipped.scattering;
      s.mesh_map_size = shipped.mesh_map_size;
      scene.shadows = s;
      RuntimeOptions ro;
      ro.width_override = o.width;
      ro.height_override = o.height;
      ChartTable::Row row;
      row.label = stem + " " + setting_name(s);
      row.front = stem;
      row.group = std::string(name_of(s.method)) +
                  (s.splat_sunlight == SplatSunlight::vertices ? " (sunlight at vertices)" : "");
      row.time = median_ms_per_frame(scene, ro, o.frames);
      ro.readback = true;
      // as written (no quality pick): images the shadow setting the chart sets
      const std::unique_ptr<SceneRuntime> imaged = open_runtime(scene, ro);
      imaged->draw_frame(0);
      if (!splats) splats = !gather_particles(imaged->world()).empty();
      row.error = image_rmse(rgb_of(imaged->image()), reference);
      row.extra = {shadow_ms_per_frame(scene, ro, o.frames), double(particle_count(imaged->world()))};
      t.rows.push_back(row);
    }
  }
  mark_pareto_front(t);
  return t;
}

}  // namespace pyro
