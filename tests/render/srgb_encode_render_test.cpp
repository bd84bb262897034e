// The passes that write the sRGB bytes themselves (content/shaders/srgb_encode.glsl, GL's own
// conversion off): the opaque pass's bytes against the exact encoding of the Lambert colour
// the scene asks for, and the final pass, run on every pixel, giving back the scene's bytes
// unchanged where nothing is composited over them (decode, then encode again).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include <glm/geometric.hpp>

#include "components/gpu_frame.h"
#include "engine/math/color.h"
#include "systems/composite/compositor.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"

namespace pyro {
namespace {

TEST(SrgbEncodeRender, OpaqueBytesAreTheExactEncodingAndComposeKeepsThem) {
  int exact = 0, total = 0;
  for (float albedo : {0.0015f, 0.01f, 0.05f, 0.13f, 0.31f, 0.55f, 0.8f}) {
    SceneDescription s;
    s.width = s.height = 32;
    s.camera.position = {0.0f, 10.0f, 0.0f};
    s.camera.target = {0.0f, 0.0f, 0.0f};
    s.camera.up = {0.0f, 0.0f, -1.0f};
    s.directional_lights.at(0).direction = {-0.3f, -1.0f, 0.2f};
    s.directional_lights.at(0).color = {1.0f, 0.9f, 0.7f};
    s.ambient_lights.at(0).color = {0.1f, 0.15f, 0.2f};
    s.render.layer_scale = 0.5f;  // the scene target is then 8-bit sRGB
    MeshDescription ground;
    ground.kind = MeshKind::ground_plane;
    ground.scale = 50.0f;
    ground.color = {albedo, albedo * 0.9f, albedo * 0.5f};
    s.meshes.push_back(ground);
    SceneRuntime run(s);
    MediaComposition m;
    m.tiles = false;  // the compose shader on every pixel (no byte copies)
    run.world().set_resource<MediaComposition>(m);
    run.step();
    const GpuFrame& frame = run.world().resource<GpuFrame>();
    ASSERT_EQ(frame.eyes[0].scene->format(), static_cast<GLenum>(GL_SRGB8_ALPHA8));
    const std::vector<uint8_t> scene = frame.eyes[0].scene->read_rgba8();
    const std::vector<uint8_t> out = frame.output->read_rgba8();
    ASSERT_EQ(scene.size(), out.size());
    const float lambert = std::max(glm::dot(glm::vec3(0, 1, 0), -glm::normalize(s.directional_lights.at(0).direction)), 0.0f);
    const glm::vec3 linear = ground.color * (s.ambient_lights.at(0).color + s.directional_lights.at(0).color * lambert);
    for (size_t i = 0; i < scene.size(); i += 4) {
      for (int c = 0; c < 3; ++c) {
        const int want = to_byte(linear_to_srgb(linear[c]));
        EXPECT_LE(std::abs(int(scene[i + c]) - want), 1) << albedo << " channel " << c;
        exact += scene[i + c] == want;
        ++total;
        EXPECT_EQ(out[i + c], scene[i + c]) << albedo << " channel " << c;
      }
    }
  }
  // Off by one only where the exact value lies within a twelfth of a step of a rounding edge.
  EXPECT_GT(exact, total * 9 / 10);
}

}  // namespace
}  // namespace pyro
