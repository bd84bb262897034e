#include "tools/import/relit_particles.h"

#include <limits>
#include <utility>

#include "components/directional_light.h"
#include "systems/runtime/cloud_import/cloud_import.h"
#include "systems/runtime/cloud_import/scene_volume.h"
#include "systems/runtime/scene_runtime/resolve_scene.h"
#include "systems/runtime/scene_runtime/scene_assets.h"

namespace pyro {

namespace {

SceneRuntime relit_runtime(VolumeAsset volume, const VolumeMedium& medium, const RelitView& view,
                           const std::optional<ShadowSettings>& shadows) {
  SceneDescription scene;
  scene.camera = view.camera;
  scene.background = glm::vec3(medium.background);
  scene.directional_lights.front().direction = glm::vec3(medium.light_direction);
  scene.directional_lights.front().color = glm::vec3(medium.light_color);
  scene.ambient_lights.front().color = glm::vec3(medium.ambient);
  scene.shadows = shadows;
  RuntimeOptions ro;
  ro.readback = view.readback;
  ro.width_override = view.width;
  ro.height_override = view.height;
  const ResolvedScene resolved = resolve_scene(scene, ro, std::numeric_limits<int>::max());
  SceneAssets assets;
  assets.volumes.push_back(std::move(volume));
  // behind the front door: a scene built from particles in memory, no scene file to open
  return SceneRuntime(resolved, std::move(assets), ro);
}

}  // namespace

SceneRuntime relit_particles_runtime(const std::vector<GaussianParticle>& particles, const VolumeMedium& medium,
                                     const RelitView& view, const std::optional<ShadowSettings>& shadows) {
  return relit_runtime({to_particle_pool(particles), {}, {}}, medium, view, shadows);
}

SceneRuntime relit_particles_runtime(const std::vector<AnisotropicGaussian>& particles, const VolumeMedium& medium,
                                     const RelitView& view, const std::optional<ShadowSettings>& shadows) {
  return relit_runtime({ParticlePool(0), particles, {}}, medium, view, shadows);
}

std::vector<GaussianParticle> import_keeping_albedo(const DenseGrid& grid, double extinction, double albedo,
                                                    double error) {
  CloudImportOptions import;
  import.medium.extinction = extinction;
  import.medium.albedo = albedo;
  import.medium.light_color = glm::dvec3(0.0);
  import.medium.ambient = glm::dvec3(1.0);
  import.tau_tolerance = tau_tolerance_for_error(error);
  return import_cloud(grid, import);
}

void set_sun(SceneRuntime& runtime, const glm::dvec3& direction) {
  runtime.world().each<DirectionalLight>([&](DirectionalLight& l) { l.direction = glm::vec3(direction); });
}

}  // namespace pyro
