// What a lit scene refuses and what --shadows changes: lit media need Gaussian particles or the
// explosion's shading (billboards shaded by their colour alone have no albedo), and the overrides
// turn a scene's lighting off or on without editing it.
#include <gtest/gtest.h>

#include <limits>

#include "engine/core/user_error.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/scene_runtime/resolve_scene.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

constexpr int kAnyTexture = std::numeric_limits<int>::max();

TEST(LitSceneRules, ColourShadedSpheresAreRefusedNamingTheKey) {
  RuntimeOptions o;
  o.shadow_method = ShadowMethod::shadow_map;
  SceneDescription explosion = load_scene(test::scene_path("explosion.json"));
  EXPECT_NO_THROW(resolve_scene(explosion, o, kAnyTexture));  // the explosion's media are lit
  explosion.render.shading = ParticleShading::color;
  try {
    resolve_scene(explosion, o, kAnyTexture);
    FAIL() << "colour-shaded spheres were lit";
  } catch (const UserError& e) {
    EXPECT_NE(std::string(e.what()).find("/shadows"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("spherical"), std::string::npos) << e.what();
  }
}

TEST(LitSceneRules, TheOverridesTurnLightingOffAndOn) {
  const SceneDescription sunset = load_scene(test::scene_path("sunset.json"));
  ASSERT_TRUE(sunset.shadows.has_value());
  RuntimeOptions off;
  off.shadows_off = true;
  EXPECT_FALSE(resolve_scene(sunset, off, kAnyTexture).scene.shadows.has_value());
  RuntimeOptions rays;
  rays.shadow_method = ShadowMethod::rays;
  const ResolvedScene lit = resolve_scene(load_scene(test::scene_path("clouds.json")), rays, kAnyTexture);
  ASSERT_TRUE(lit.scene.shadows.has_value());
  EXPECT_EQ(lit.scene.shadows->method, ShadowMethod::rays);
  EXPECT_EQ(lit.scene.shadows->map_size, ShadowSettings{}.map_size);
}

}  // namespace
}  // namespace pyro
