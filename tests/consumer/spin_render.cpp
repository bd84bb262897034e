// An embedding program: a scene made in code (no file), the engine's layered runtime, one entity
// built by hand with the consumer's own component (a single Gaussian particle that spins about a
// vertical axis), the consumer's own system added to the standard schedule, frames rendered
// headless (EGL) and the last one written as a PNG. Then it checks the picture against what the
// spin system must have produced: the particle's image is centred where the camera projects
// the particle's position turned by rate x time about the axis (closed form, glm's own camera
// matrices), not where it started.
//
//   spin_render --out FILE.png     exit 0 when the check holds, 1 when it does not, 2 on bad use
#include <cmath>
#include <cstdio>
#include <cstring>
#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>
#include <numbers>
#include <string>

#include "components/particle_set.h"
#include "engine/io/png_file.h"
#include "spin/spin.h"
#include "spin/spin_system.h"
#include "systems/output/png_sink.h"
#include "systems/runtime/scene/scene_description.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"

namespace {

constexpr int kWidth = 240, kHeight = 180;
constexpr float kFps = 24.0f;
constexpr int kFrames = 13;  // frames 0..12: frame 0 as built, then 12 turns of rate / fps
const glm::vec3 kAxis{0.0f, 1.0f, 0.0f};   // a point of the vertical spin axis
const glm::vec3 kStart{1.5f, 1.6f, 0.0f};  // where the particle starts (above the eye)
constexpr float kRate = std::numbers::pi_v<float> / 2.0f;  // radians per second

pyro::SceneDescription spin_scene() {
  pyro::SceneDescription scene;
  scene.name = "spin";
  scene.width = kWidth;
  scene.height = kHeight;
  scene.frames_per_second = kFps;
  scene.background = {0.02f, 0.02f, 0.03f};
  scene.camera.position = {0.0f, 1.0f, 6.0f};
  scene.camera.target = {0.0f, 1.0f, 0.0f};
  return scene;
}

void add_spinning_particle(pyro::ecs::World& world) {
  pyro::ParticlePool pool(1);
  pool.spawn({.position = kStart, .radius = 0.35f, .density = 4.0f, .color = {1.0f, 0.9f, 0.6f}});
  const pyro::ecs::Entity e = world.create();
  world.emplace<pyro::ParticleSet>(e, pyro::ParticleSet{std::move(pool)});
  world.emplace<spin::Spin>(e, spin::Spin{kAxis, kRate});
}

// Pixel (x right, y down, pixel centres at +0.5) where the scene's camera sees p.
glm::vec2 project(const pyro::SceneDescription& scene, const glm::vec3& p) {
  const pyro::CameraDescription& c = scene.camera;
  const glm::mat4 view = glm::lookAt(c.position, c.target, c.up);
  const glm::mat4 proj = glm::perspective(glm::radians(c.fov_y_deg),
                                          float(scene.width) / float(scene.height), c.near, c.far);
  const glm::vec4 clip = proj * view * glm::vec4(p, 1.0f);
  const glm::vec2 ndc{clip.x / clip.w, clip.y / clip.w};
  return {(ndc.x * 0.5f + 0.5f) * scene.width, (0.5f - ndc.y * 0.5f) * scene.height};
}

// Where the spin system must have put the particle: kStart turned counter-clockwise (seen from
// +y) by kRate times the frames after frame 0 over the frame rate.
glm::vec3 expected_position() {
  const float a = kRate * float(kFrames - 1) / kFps;
  const float x = kStart.x - kAxis.x, z = kStart.z - kAxis.z;
  return {kAxis.x + std::cos(a) * x + std::sin(a) * z, kStart.y,
          kAxis.z - std::sin(a) * x + std::cos(a) * z};
}

// The centre of what differs from the background (the corner pixel), weighted by how much.
glm::vec2 image_centroid(const pyro::PngImage& img) {
  const auto at = [&](int x, int y, int c) {
    return int(img.pixels[(size_t(y) * img.width + x) * img.channels + c]);
  };
  double sx = 0, sy = 0, sw = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      int w = 0;
      for (int c = 0; c < 3; ++c) w += std::abs(at(x, y, c) - at(0, 0, c));
      if (w <= 3) continue;  // below a rounding step per channel: background
      sx += w * (x + 0.5);
      sy += w * (y + 0.5);
      sw += w;
    }
  if (sw == 0) return {-1.0f, -1.0f};
  return {float(sx / sw), float(sy / sw)};
}

}  // namespace

int main(int argc, char** argv) {
  const std::string out = argc == 3 && std::strcmp(argv[1], "--out") == 0 ? argv[2] : "";
  if (out.size() < 5 || out.substr(out.size() - 4) != ".png") {
    std::fprintf(stderr, "usage: spin_render --out FILE.png\n");
    return 2;
  }
  const pyro::SceneDescription scene = spin_scene();
  pyro::RuntimeOptions options;
  options.readback = false;
  options.extra_systems.push_back(spin::spin_system());  // into the standard schedule
  pyro::SceneRuntime runtime(scene, options);
  add_spinning_particle(runtime.world());
  for (int f = 0; f < kFrames; ++f) runtime.step();
  pyro::write_shown_png(runtime.read_shown(), out.substr(0, out.size() - 4), false);

  const pyro::PngImage img = pyro::read_png(out);
  const glm::vec2 seen = image_centroid(img);
  const glm::vec2 want = project(scene, expected_position());
  const glm::vec2 start = project(scene, kStart);
  const float error = glm::length(seen - want), moved = glm::length(want - start);
  std::printf(
      "{\"file\": \"%s\", \"centroid\": [%.2f, %.2f], \"expected\": [%.2f, %.2f], "
      "\"start\": [%.2f, %.2f], \"error_px\": %.3f}\n",
      out.c_str(), seen.x, seen.y, want.x, want.y, start.x, start.y, error);
  // The spin moves the image by `moved` pixels; the centroid must land within one pixel.
  if (img.width != kWidth || img.height != kHeight || error > 1.0f || moved < 8.0f) {
    std::fprintf(stderr, "spin_render: the particle's image is not where the spin put it\n");
    return 1;
  }
  return 0;
}
