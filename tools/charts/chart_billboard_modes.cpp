// pyro chart billboard-modes: viewplane- and viewpoint-facing Gaussian billboards (Johnson &
// McAllister 2005, section 3) and spherical billboards (Umenhoffer et al. 2006) on the clouds,
// fog and explosion scenes, each image against the CPU reference of the same particles.
#include <filesystem>
#include <memory>
#include <string>

#include "components/frame_image.h"
#include "components/particle_set.h"
#include "components/render_settings.h"
#include "components/view.h"
#include "engine/core/content_path.h"
#include "systems/runtime/open_scene/open_scene.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/reference/particle_reference.h"
#include "systems/runtime/reference/world_snapshot.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"
#include "tools/charts/charts.h"
#include "tools/bench/frame_timing.h"

namespace pyro {

namespace {

struct Mode {
  ParticleShape shape;
  BillboardAlignment alignment;
  // Gaussian splats by their alignment, spherical billboards by their shape.
  std::string name() const {
    return std::string(shape == ParticleShape::gaussian ? name_of(alignment) : name_of(shape));
  }
};

constexpr Mode kModes[] = {
    {ParticleShape::gaussian, BillboardAlignment::viewplane},
    {ParticleShape::gaussian, BillboardAlignment::viewpoint},
    {ParticleShape::spherical, BillboardAlignment::viewplane},
};

}  // namespace

ChartTable chart_billboard_modes(const BillboardModesChartOptions& o) {
  std::vector<std::string> scenes = o.scenes;
  if (scenes.empty())
    for (const char* s : {"scenes/clouds.json", "scenes/fog.json", "scenes/explosion.json"})
      scenes.push_back(content_path(s));
  ChartTable t;
  t.name = "billboard-modes";
  t.title = "Billboard modes against the CPU reference (" + std::to_string(o.width) + "x" +
            std::to_string(o.height) + ", particles only)";
  t.x_label = "ms per frame (mono)";
  t.y_label = "RMSE (linear RGB) against the CPU particle reference";
  t.ground_truth =
      "the CPU reference of the same particles at the same frame (systems/runtime/reference/"
      "particle_reference.h: the exact sum of clamped Gaussians, erf integrals along each ray)";
  t.notes = {"the scenes' meshes are left out and every particle is drawn with its own colour "
             "(shading: color), so the reference models exactly what is drawn; the explosion's "
             "media shading is not modelled by the reference",
             "spherical: a sphere of homogeneous medium whose extinction is the particle's "
             "density (Umenhoffer et al. 2006) - a different medium from the Gaussian, so its "
             "error includes the change of model, not only projection",
             "the viewplane-viewpoint difference per eye: pyro analyze billboard-modes SCENE --json"};
  t.extra_columns = {"particles"};
  for (const std::string& file : scenes) {
    SceneDescription scene = load_scene(file);
    prepare_scene_run(scene);  // before the timed runtimes (tools/bench/frame_timing.h) open it
    scene.meshes.clear();
    const std::string stem = std::filesystem::path(file).stem().string();
    for (const Mode& m : kModes) {
      RuntimeOptions ro;
      ro.width_override = o.width;
      ro.height_override = o.height;
      ro.particles = m.shape;
      ro.alignment = m.alignment;
      ro.shading = ParticleShading::color;
      ro.layer_scale = 1.0f;
      const double ms = median_ms_per_frame(scene, ro, o.frames);
      ro.readback = true;
      // as written (no quality pick): images each billboard mode at the settings the chart sets
      const std::unique_ptr<SceneRuntime> imaged = open_runtime(scene, ro);
      imaged->step();
      const RgbImage splat = rgb_of(imaged->image());
      const ParticlePool pool = gather_particles(imaged->world());
      const CameraFrame& camera = imaged->world().resource<View>().eyes.at(0);
      const RgbImage reference = render_particles_reference(
          pool, camera, glm::dvec3(imaged->world().resource<RenderSettings>().background));
      ChartTable::Row row;
      row.label = stem + " " + m.name();
      row.front = stem;
      row.group = m.name();
      row.time = ms;
      row.error = image_rmse(reference, splat);
      row.extra = {double(pool.size())};
      t.rows.push_back(row);
    }
  }
  mark_pareto_front(t);
  return t;
}

}  // namespace pyro
