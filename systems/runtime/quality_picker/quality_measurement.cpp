#include "systems/runtime/quality_picker/quality_measurement.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>

#include "components/anisotropic_cloud.h"
#include "components/fire_lights.h"
#include "components/frame_image.h"
#include "components/gpu_frame.h"
#include "components/mesh_shadow.h"
#include "components/particle_set.h"
#include "components/scene_lighting.h"
#include "components/shadow_settings.h"
#include "components/view.h"
#include "engine/core/sample_statistics.h"
#include "engine/core/user_error.h"
#include "engine/ecs/world.h"
#include "systems/runtime/reference/anisotropic_reference.h"
#include "systems/runtime/reference/lit_particle_reference.h"
#include "systems/runtime/reference/particle_reference.h"
#include "systems/shadowing/mesh_shadow_map.h"
#include "systems/runtime/reference/world_snapshot.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"

namespace pyro {

namespace {

constexpr int kTruthSubsteps = 4;

// Mono at width x height, with `q` (a quality pick: its substeps make the runtime's frames finer
// than the scene's; SceneRuntime::draw_frame counts in the scene's frames).
RuntimeOptions mono_options(int width, int height, bool readback,
                            std::optional<QualitySettings> q = std::nullopt) {
  RuntimeOptions o;
  o.readback = readback;
  o.width_override = width;
  o.height_override = height;
  o.quality = q;
  return o;
}

// The opaque scene alone (meshes and background), unshadowed; `sunless`: without its sun.
SceneDescription opaque_part(const SceneDescription& scene, bool sunless) {
  SceneDescription opaque = scene;
  opaque.clouds.clear();
  opaque.volumes.clear();
  opaque.emitters.clear();
  // Lit, the flipbook fires still light the ground (unshadowed, as the engine's opaque pass);
  // without fires the opaque scene is drawn unlit and its sun shadowed by the reference.
  if (opaque.fires.empty()) opaque.shadows.reset();
  opaque.render.layer_scale = 1.0f;
  if (!sunless) return opaque;
  for (DirectionalLight& light : opaque.directional_lights) light.intensity = 0.0f;
  for (LightKeyframes& keys : opaque.light_keyframes)
    for (LightKeyframe& key : keys.keys) key.intensity = 0.0f;
  return opaque;
}

// Every anisotropic cloud's particles, in the order the billboard system draws them.
std::vector<AnisotropicGaussian> anisotropic_particles(ecs::World& world) {
  std::vector<AnisotropicGaussian> all;
  world.each<const AnisotropicCloud>([&](const AnisotropicCloud& c) {
    all.insert(all.end(), c.particles.begin(), c.particles.end());
  });
  return all;
}

}  // namespace

std::vector<RgbImage> particle_scene_references(const SceneDescription& scene, int width, int height,
                                                const std::vector<int>& frames) {
  // The particles' state and camera from the scene as given (clouds drift linearly, so the time
  // step changes nothing), the opaque scene from a render without particles.
  SceneRuntime particles(scene, mono_options(width, height, false));
  SceneRuntime background(opaque_part(scene, false), mono_options(width, height, true));
  std::optional<SceneRuntime> sunless;
  if (scene.shadows) sunless.emplace(opaque_part(scene, true), mono_options(width, height, true));
  std::vector<RgbImage> images;
  for (int f : frames) {
    particles.draw_frame(f);
    background.draw_frame(f);
    const CameraFrame camera = particles.world().resource<View>().eyes.at(0);
    const RgbImage behind = rgb_of(background.image());
    const std::vector<float> stop =
        ray_stop_distances(camera, background.world().resource<GpuFrame>().eyes.at(0).scene->read_depth());
    const ParticlePool pool = gather_particles(particles.world());
    const std::vector<AnisotropicGaussian> fitted = anisotropic_particles(particles.world());
    if (!fitted.empty() && pool.size() > 0)
      throw UserError(scene.file.empty() ? "scene" : scene.file, "/volumes",
                      "one kind of Gaussian for the CPU reference (the quality picker's and the charts' truth): "
                      "isotropic particles or a fitted (version 2) particle file, found both");
    if (!sunless) {
      images.push_back(fitted.empty() ? render_particles_reference_over(pool, camera, behind, stop)
                                      : render_anisotropic_reference_over(fitted, camera, behind, stop));
      continue;
    }
    // Lit media: single scattering with exact shadows, over the opaque scene with its shadows.
    sunless->draw_frame(f);
    const SceneLighting& lighting = particles.world().resource<const SceneLighting>();
    ReferenceSun sun;
    sun.travel = glm::dvec3(lighting.key() ? lighting.key()->travel : SunLight{}.travel);
    sun.color = glm::dvec3(lighting.key_radiance());
    sun.ambient = glm::dvec3(lighting.ambient);
    if (const auto* shadows = particles.world().try_resource<const ShadowSettings>())
      sun.scattering = shadows->scattering;
    if (const auto* fire = particles.world().try_resource<const FireLights>()) sun.point_lights = fire->lights;
    if (const auto* meshes = particles.world().try_resource<const MeshShadow>(); meshes && !meshes->empty()) {
      sun.mesh_depth = [meshes](const glm::dvec3& p) { return mesh_shadow_depth(*meshes, glm::vec3(p)); };
      // A surface point read back from the depth buffer, on a face at any slant: 4 texels of bias.
      sun.mesh_surface_depth = [meshes](const glm::dvec3& p) { return mesh_shadow_depth(*meshes, glm::vec3(p), 4.0); };
    }
    if (!fitted.empty()) {
      const RgbImage shadowed =
          shadowed_opaque_reference(anisotropic_casters(fitted), camera, sun, behind, rgb_of(sunless->image()), stop);
      images.push_back(render_lit_anisotropic_reference_over(fitted, camera, sun, shadowed, stop));
      continue;
    }
    const RgbImage shadowed =
        shadowed_opaque_reference(pool, camera, sun, behind, rgb_of(sunless->image()), stop);
    images.push_back(render_lit_particles_reference_over(pool, camera, sun, shadowed, stop));
  }
  return images;
}

bool gaussian_particles(const SceneDescription& scene) {
  const auto gaussian = [&](const std::optional<ParticleShape>& own) {
    return own.value_or(scene.render.particles) == ParticleShape::gaussian;
  };
  return gaussian(std::nullopt) &&
         std::all_of(scene.clouds.begin(), scene.clouds.end(), [&](const CloudDescription& c) { return gaussian(c.particles); }) &&
         std::all_of(scene.emitters.begin(), scene.emitters.end(), [&](const EmitterDescription& e) { return gaussian(e.particles); });
}

bool has_dynamics(const SceneDescription& scene) { return !scene.emitters.empty(); }

QualityGroundTruth::QualityGroundTruth(const SceneDescription& scene, int width, int height,
                                       std::vector<int> frames)
    : frames_(std::move(frames)) {
  const auto t0 = std::chrono::steady_clock::now();
  cpu_reference_ = gaussian_particles(scene);
  if (cpu_reference_) {
    images_ = particle_scene_references(scene, width, height, frames_);
  } else {
    QualitySettings finest;
    finest.layer_scale = 1.0f;
    finest.footprint_size = scene.footprint.size;
    finest.substeps = has_dynamics(scene) ? kTruthSubsteps : 1;
    if (scene.shadows) {  // lit explosions: every fragment's light summed over every particle
      finest.shadows = shadow_choice(*scene.shadows);
      finest.shadows->exact_fragments = true;
    }
    SceneRuntime runtime(scene, mono_options(width, height, true, finest));
    for (int f : frames_) {
      runtime.draw_frame(f);
      images_.push_back(rgb_of(runtime.image()));
    }
  }
  seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

std::string QualityGroundTruth::description() const {
  return cpu_reference_
             ? "CPU reference (exact Gaussian integrals) over the GL-rendered opaque scene"
             : "converged GL render (layers at full resolution, 4 substeps per frame, lit media "
               "summed exactly per fragment): no CPU reference exists for spherical or "
               "explosion-shaded particles";
}

double measure_rmse(const SceneDescription& scene, int width, int height, const QualitySettings& q,
                    const QualityGroundTruth& truth) {
  SceneRuntime runtime(scene, mono_options(width, height, true, q));
  double sum = 0.0;
  for (size_t k = 0; k < truth.frames().size(); ++k) {
    runtime.draw_frame(truth.frames()[k]);
    const double e = image_rmse(rgb_of(runtime.image()), truth.image(k));
    sum += e * e;
  }
  return truth.frames().empty() ? 0.0 : std::sqrt(sum / double(truth.frames().size()));
}

double measure_ms_per_frame(const SceneDescription& scene, int width, int height,
                            const QualitySettings& q, int frames) {
  SceneRuntime runtime(scene, mono_options(width, height, false, q));
  runtime.draw_frame(0);  // warm up: shaders, tables, targets
  glFinish();
  // The fastest frame: other work on a shared machine only ever adds time, so the least
  // disturbed frame estimates the setting's own cost best (a mean or median follows the load).
  std::vector<double> ms;
  for (int f = 1; f <= std::max(1, frames); ++f) {
    const auto t0 = std::chrono::steady_clock::now();
    runtime.draw_frame(f);
    glFinish();
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  }
  return sample_statistics(ms).min;
}

}  // namespace pyro
