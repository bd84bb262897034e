// What a lit scene refuses and what --shadows changes: lit media need Gaussian particles (an
// explosion's spheres keep their own shading), and the overrides turn a scene's lighting off or
// on without editing it.
#include <gtest/gtest.h>

#include <limits>

#include "engine/core/user_error.h"
#include "systems/scene/scene_loader.h"
#include "systems/scene_runtime/resolve_scene.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

constexpr int kAnyTexture = std::numeric_limits<int>::max();

TEST(LitSceneRules, SphericalParticlesAreRefusedNamingTheKey) {
  RuntimeOptions o;
  o.shadow_method = ShadowMethod::shadow_map;
  try {
    resolve_scene(load_scene(test::scene_path("explosion.json")), o, kAnyTexture);
    FAIL() << "an explosion was lit";
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
