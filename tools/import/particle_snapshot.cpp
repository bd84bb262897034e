#include "tools/import/particle_snapshot.h"

#include "systems/runtime/cloud_import/scene_volume.h"

#include <algorithm>
#include <chrono>

#include "components/frame_image.h"
#include "components/particle_set.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"

namespace pyro {

RgbImage render_particle_snapshot(const std::vector<GaussianParticle>& particles,
                                  const CameraDescription& camera, int width, int height,
                                  const glm::vec3& background, int repeats,
                                  SnapshotTiming* timing) {
  SceneDescription scene;
  scene.width = width;
  scene.height = height;
  scene.background = background;
  scene.camera = camera;
  SceneRuntime runtime(scene);  // behind the front door: a synthetic scene the benchmark fills
  ecs::World& world = runtime.world();
  world.emplace<ParticleSet>(world.create(), ParticleSet{to_particle_pool(particles)});
  double best = 1e300;
  for (int k = 0; k < std::max(1, repeats); ++k) {
    const auto t0 = std::chrono::steady_clock::now();
    runtime.step();
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  if (timing) timing->render_seconds = best;
  const FrameImage& img = runtime.image();
  RgbImage out;
  out.width = img.width;
  out.height = img.height;
  out.rgb.resize(size_t(3) * img.width * img.height);
  for (size_t i = 0; i < size_t(img.width) * img.height; ++i)
    for (int c = 0; c < 3; ++c) out.rgb[3 * i + c] = img.rgba[4 * i + c];
  return out;
}

}  // namespace pyro
