#include "systems/runtime/scene_runtime/resolve_scene.h"

#include "systems/runtime/scene/scene_budget.h"

#include <string>

#include "engine/core/user_error.h"

namespace pyro {

namespace {

RenderSettings merge_render_settings(const SceneDescription& scene, const RuntimeOptions& options) {
  RenderSettings s;
  s.width = options.width_override > 0 ? options.width_override : scene.width;
  s.height = options.height_override > 0 ? options.height_override : scene.height;
  s.background = scene.background;
  s.transparent = options.background.value_or(scene.output_background) == OutputBackground::none;
  s.alignment = options.alignment.value_or(scene.render.billboards);
  s.particles = options.particles.value_or(scene.render.particles);
  s.layer_scale = options.layer_scale.value_or(scene.render.layer_scale);
  s.frame_scale = options.frame_scale;
  s.stereo_mode = options.stereo_mode;
  s.shading = options.shading.value_or(scene.render.shading);
  s.motion_blur = scene.render.motion_blur;
  s.sort_device = options.sort_device.value_or(scene.render.sort_device);
  return s;
}

ExplosionShading explosion_shading(const RenderDescription& render) {
  ExplosionShading shading;
  shading.fire_t_min = render.fire_t_min;
  shading.fire_t_max = render.fire_t_max;
  shading.fire_emission = render.fire_emission;
  shading.fire_detail_range = render.fire_detail_range;
  return shading;
}

StereoCamera stereo_camera(const CameraDescription& camera, const RuntimeOptions& options) {
  StereoCamera stereo;
  stereo.parameters.interocular = options.interocular.value_or(camera.interocular);
  stereo.parameters.zero_parallax_distance =
      options.zero_parallax_distance.value_or(camera.zero_parallax_distance);
  stereo.eye_order =
      options.swap_eyes.value_or(camera.swap_eyes) ? EyeOrder::right_left : EyeOrder::left_right;
  return stereo;
}

// The command line's --particles draws every set as one kind, to compare kinds: the sets' own
// kinds are dropped.
void drop_particle_kinds(SceneDescription& scene) {
  for (CloudDescription& c : scene.clouds) c.particles.reset();
  for (EmitterDescription& e : scene.emitters) e.particles.reset();
}

// A set's own kind is honoured only where its renderer can draw it beside the others: the
// explosion's media layers shade every set as render.particles, and the light phase lights
// Gaussian splats only (resolve_scene refuses other scene-wide kinds with shadows).
void check_particle_kind(const ResolvedScene& r, const std::optional<ParticleShape>& kind,
                         const std::string& file, const std::string& pointer) {
  if (!kind || *kind == r.settings.particles) return;
  const std::string found = "found \"" + std::string(name_of(*kind)) + "\"";
  if (r.settings.shading == ParticleShading::explosion)
    throw UserError(file, pointer,
                    "with \"shading\": \"explosion\" every set is drawn as render.particles (\"" +
                        std::string(name_of(r.settings.particles)) + "\"); " + found +
                        " (drop the key or use \"shading\": \"color\")");
  if (r.scene.shadows && *kind != ParticleShape::gaussian)
    throw UserError(file, pointer,
                    "lit media (\"shadows\") light Gaussian particles only; " + found +
                        " shaded by colour (docs/lighting.md)");
}

void check_particle_kinds(const ResolvedScene& r, const std::string& file) {
  for (size_t i = 0; i < r.scene.clouds.size(); ++i)
    check_particle_kind(r, r.scene.clouds[i].particles, file, "/clouds/" + std::to_string(i) + "/particles");
  for (size_t i = 0; i < r.scene.emitters.size(); ++i)
    check_particle_kind(r, r.scene.emitters[i].particles, file, "/emitters/" + std::to_string(i) + "/particles");
}

}  // namespace

ResolvedScene resolve_scene(const SceneDescription& scene, const RuntimeOptions& options,
                            int driver_max_texture) {
  ResolvedScene r;
  r.scene = options.quality ? apply_quality_settings(scene, *options.quality) : scene;
  if (options.shadows_off) r.scene.shadows.reset();
  else if (options.shadow_method) r.scene.shadows.emplace(r.scene.shadows.value_or(ShadowSettings{})).method = *options.shadow_method;
  r.quality = options.quality;
  r.substeps = options.quality ? options.quality->substeps : 1;
  r.settings = merge_render_settings(r.scene, options);
  if (options.particles) drop_particle_kinds(r.scene);
  // The light phase lights Gaussian splats and the explosion's media; spherical and planar
  // billboards shaded by their colour alone have no albedo to light.
  if (r.scene.shadows && r.settings.particles != ParticleShape::gaussian && !r.settings.media_layers())
    throw UserError(scene.file.empty() ? "scene" : scene.file, "/shadows",
                    "lit media with Gaussian particles or \"shading\": \"explosion\"; found \"particles\": \"" +
                        std::string(name_of(r.settings.particles)) +
                        "\" shaded by colour (docs/lighting.md)");
  check_particle_kinds(r, scene.file.empty() ? "scene" : scene.file);
  r.shading = explosion_shading(r.scene.render);
  r.stereo = stereo_camera(r.scene.camera, options);
  r.clock.dt = 1.0f / r.scene.frames_per_second;
  r.views = is_stereo(r.settings.stereo_mode) ? 2 : 1;
  r.output_width = output_width(r.settings.width, r.settings.stereo_mode);
  r.driver_max_texture = driver_max_texture;
  check_resolved_budget(r, 0);
  return r;
}

void check_resolved_budget(const ResolvedScene& r, uint64_t volume_particles) {
  check_scene_budget(r.scene,
                     estimate_scene_cost(r.scene, r.settings.width, r.settings.height, r.views,
                                         r.output_width, volume_particles),
                     r.driver_max_texture);
}

}  // namespace pyro
