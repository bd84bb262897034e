#include "tools/analyze/six_way_error.h"

#include <chrono>
#include <cmath>
#include <limits>
#include <memory>

#include "components/shadow_settings.h"
#include "components/view.h"
#include "systems/runtime/open_scene/open_scene.h"
#include "systems/runtime/reference/lit_particle_reference.h"
#include "systems/runtime/reference/world_snapshot.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"
#include "tools/bake/six_way_bake.h"

namespace pyro {

namespace {

// The reference's pass: the particles lit by the pass's light over black, uncut.
RgbImage reference_pass(const ParticlePool& pool, const CameraFrame& camera,
                        const SunScattering& scattering, const SixWayPassLight& pass) {
  ReferenceSun sun;
  sun.travel = glm::dvec3(pass.travel);
  sun.color = glm::dvec3(pass.sun);
  sun.ambient = glm::dvec3(pass.ambient);
  sun.scattering = scattering;
  RgbImage black;
  black.width = camera.width;
  black.height = camera.height;
  black.rgb.assign(static_cast<size_t>(camera.width) * camera.height * 3, 0.0f);
  const std::vector<float> stop(static_cast<size_t>(camera.width) * camera.height,
                                std::numeric_limits<float>::infinity());
  return render_lit_particles_reference_over(pool, camera, sun, black, stop);
}

SixWayPassLight diagonal_pass(const CameraFrame& camera, const glm::vec3& towards_light) {
  SixWayPassLight pass;
  pass.travel = six_way_light_travel(camera, towards_light);
  return pass;
}

// Images of one size side by side, left to right.
RgbImage side_by_side(const std::vector<const RgbImage*>& images) {
  RgbImage out;
  out.height = images.front()->height;
  for (const RgbImage* image : images) out.width += image->width;
  out.rgb.assign(static_cast<size_t>(out.width) * out.height * 3, 0.0f);
  int x0 = 0;
  for (const RgbImage* image : images) {
    for (int y = 0; y < image->height; ++y)
      for (int x = 0; x < image->width; ++x)
        for (int c = 0; c < 3; ++c) out.at(x0 + x, y)[c] = image->at(x, y)[c];
    x0 += image->width;
  }
  return out;
}

}  // namespace

std::vector<glm::vec3> six_way_diagonals() {
  std::vector<glm::vec3> d;
  const float s = 1.0f / std::sqrt(3.0f);
  for (float x : {1.0f, -1.0f})
    for (float y : {1.0f, -1.0f})
      for (float z : {1.0f, -1.0f}) d.push_back(glm::vec3(x, y, z) * s);
  return d;
}

SixWayErrorReport measure_six_way_error(const SceneDescription& scene,
                                        const SixWayErrorOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  SixWayBakeOptions bake;
  bake.frames = 1;
  bake.loop_blend = 0;
  bake.width = options.width;
  bake.height = options.height;
  check_six_way_bake(scene, bake, "");
  const std::unique_ptr<SceneRuntime> opened = open_runtime(scene, six_way_runtime_options(bake));
  SceneRuntime& runtime = *opened;
  runtime.draw_frame(options.frame);
  const CameraFrame camera = runtime.world().resource<View>().eyes.at(0);
  const ParticlePool pool = gather_particles(runtime.world());
  const SunScattering scattering = scene.shadows->scattering;
  const auto reference = [&](const SixWayPassLight& pass) {
    return reference_pass(pool, camera, scattering, pass);
  };

  const SixWayFrame engine_bake = unpack_six_way(pack_six_way(render_six_way_frame(runtime)));
  const SixWayRenders reference_renders = render_six_way_passes(camera, reference);
  const SixWayFrame reference_bake =
      six_way_frame_from_renders(reference_renders.faces, reference_renders.opacity);

  SixWayErrorReport report;
  report.particles = pool.size();
  std::vector<RgbImage> shown;
  for (const glm::vec3& d : six_way_diagonals()) {
    const RgbImage truth = reference(diagonal_pass(camera, d));
    const RgbImage relit = relight_six_way(engine_bake, d);
    SixWayDirectionError e;
    e.towards_light = d;
    e.six_way_engine = image_rmse(relit, truth);
    e.six_way_reference = image_rmse(relight_six_way(reference_bake, d), truth);
    const RgbImage engine_lit = render_six_way_pass(runtime, diagonal_pass(camera, d));
    e.engine_lit = image_rmse(engine_lit, truth);
    e.six_way_engine_vs_engine_lit = image_rmse(relit, engine_lit);
    report.directions.push_back(e);
    if ((d.x > 0 && d.y > 0 && d.z > 0) || (d.x < 0 && d.y > 0 && d.z < 0)) {
      shown.push_back(truth);
      shown.push_back(relit);
    }
  }
  report.picture = side_by_side({&shown[0], &shown[1], &shown[2], &shown[3]});
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return report;
}

}  // namespace pyro
