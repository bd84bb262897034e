// Spherical and planar billboards drawn as point sprites (systems/billboard_render/
// sphere_billboard_programs.h) give the image the quads give: the primitive only decides which
// pixels the fragment shader runs on, and both cover the sphere's image (or the planar square)
// whole. Checked on the paper's explosion seen from inside it, where spheres around the eye
// are drawn as quads between sprites (runs that must keep the back-to-front order) and many
// sprites have their centres off the view; as media layers at 1/2 and at full size, spherical
// and planar, and in stereo (off-axis eyes, side by side).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "components/draw_list.h"
#include "components/frame_image.h"
#include "components/render_settings.h"
#include "components/view.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/billboard_render/sphere_billboard_programs.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"

namespace pyro {
namespace {

struct Render {
  std::vector<float> image;
  size_t sprites = 0, quads = 0, off_view_sprites = 0;
};

Render render_billboard_sprites(float layer_scale, ParticleShape shape, StereoMode mode, bool sprites) {
  SceneDescription scene =
      load_scene(std::string(PYRO_SOURCE_DIR) + "/content/scenes/explosion.json");
  scene.camera.position = {1.2f, 2.2f, 2.6f};  // inside the smoke, looking across the fire
  scene.camera.target = {-3.0f, 2.0f, -1.0f};
  RuntimeOptions o;
  o.width_override = 160;
  o.height_override = 120;
  o.layer_scale = layer_scale;
  o.particles = shape;
  o.stereo_mode = mode;
  SceneRuntime run(scene, o);
  run.world().resource<RenderSettings>().billboard_sprites = sprites;
  for (int f = 0; f < 10; ++f) run.step();
  Render r;
  r.image = run.image().rgba;
  // Which primitive each particle of the first eye took, as the renderer decides it.
  const CameraFrame& eye = run.world().resource<View>().eyes[0];
  const glm::vec2 layer = glm::ceil(glm::vec2(160.0f, 120.0f) * layer_scale);
  GLfloat range[2] = {1.0f, 1.0f};
  glGetFloatv(GL_POINT_SIZE_RANGE, range);
  const DrawList& list = run.world().resource<EyeDrawLists>().eyes[0];
  for (size_t i = 0; i < list.size(); ++i) {
    const glm::vec4& c = list.center_radius[i];
    const glm::vec3 v = glm::vec3(eye.view * glm::vec4(glm::vec3(c), 1.0f));
    const bool sprite = sphere_billboard_sprite(v, c.w, eye, layer, shape == ParticleShape::planar,
                                                range[1]).has_value();
    (sprite ? r.sprites : r.quads) += 1;
    const glm::vec4 q = eye.projection * glm::vec4(v, 1.0f);
    if (sprite && (std::abs(q.x / q.w) > 1.0f || std::abs(q.y / q.w) > 1.0f)) ++r.off_view_sprites;
  }
  return r;
}

float largest_difference(const std::vector<float>& a, const std::vector<float>& b) {
  EXPECT_EQ(a.size(), b.size());
  float worst = 0.0f;
  for (size_t i = 0; i < a.size() && i < b.size(); ++i) worst = std::max(worst, std::abs(a[i] - b[i]));
  return worst;
}

TEST(BillboardSprites, SameImageAsQuads) {
  struct Case {
    float scale;
    ParticleShape shape;
    StereoMode mode;
  };
  for (const Case& c : {Case{0.5f, ParticleShape::spherical, StereoMode::mono},
                        Case{1.0f, ParticleShape::spherical, StereoMode::mono},
                        Case{0.5f, ParticleShape::planar, StereoMode::mono},
                        Case{0.5f, ParticleShape::spherical, StereoMode::side_by_side}}) {
    const Render sprites = render_billboard_sprites(c.scale, c.shape, c.mode, true);
    const Render quads = render_billboard_sprites(c.scale, c.shape, c.mode, false);
    // The view mixes both primitives, and sprites centred off the view.
    EXPECT_GT(sprites.sprites, 20u) << c.scale;
    EXPECT_GT(sprites.quads, 0u) << c.scale;
    EXPECT_GT(sprites.off_view_sprites, 0u) << c.scale;
    EXPECT_LT(largest_difference(sprites.image, quads.image), 2e-3f)
        << c.scale << " " << static_cast<int>(c.shape) << " " << static_cast<int>(c.mode);
  }
}

}  // namespace
}  // namespace pyro
