// The light block (components/light_block.h): pack_lights puts every sun, the ambient term and
// the fire's clustered lights where the C++ layout says, and a shader that includes
// content/shaders/lights.glsl reads back exactly those values through the LightBuffer (the GLSL
// block and the C++ struct agree word for word).
#include "systems/lighting/light_block.h"

#include <gtest/gtest.h>

#include <epoxy/gl.h>

#include <cstring>
#include <stdexcept>
#include <vector>

#include "engine/gpu/shader_program.h"
#include "systems/lighting/light_buffer.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"

namespace pyro {
namespace {

SceneLighting three_suns() {
  SceneLighting l;
  l.suns = {SunLight({0.0f, -2.0f, 0.0f}, {1.0f, 0.5f, 0.25f}), SunLight({3.0f, 0.0f, 4.0f}, {0.1f, 0.2f, 0.3f}),
            SunLight({0.0f, 0.0f, 0.0f}, {7.0f, 8.0f, 9.0f})};
  l.ambient = {0.25f, 0.125f, 0.0625f};
  return l;
}

FireLights fire_lights(int count) {
  FireLights fire;
  for (int j = 0; j < count; ++j)
    fire.lights.push_back({glm::dvec3(j, 2.0 * j, -j), glm::dvec3(10.0 + j, 20.0, 30.0), 0.5 + j});
  return fire;
}

TEST(LightBlock, HoldsEverySunInOrderTheAmbientTermAndTheFireLights) {
  const FireLights fire = fire_lights(3);
  const LightBlock b = pack_lights(three_suns(), &fire);
  EXPECT_EQ(b.counts, glm::ivec4(3, 3, 0, 0));
  EXPECT_EQ(b.ambient, glm::vec4(0.25f, 0.125f, 0.0625f, 0.0f));
  EXPECT_EQ(b.sun_toward[0], glm::vec4(0.0f, 1.0f, 0.0f, 0.0f));
  EXPECT_EQ(b.sun_travel[0], glm::vec4(0.0f, -2.0f, 0.0f, 0.0f));
  EXPECT_NEAR(b.sun_toward[1].x, -0.6f, 1e-7f);
  EXPECT_NEAR(b.sun_toward[1].z, -0.8f, 1e-7f);
  EXPECT_EQ(b.sun_radiance[1], glm::vec4(0.1f, 0.2f, 0.3f, 0.0f));
  EXPECT_EQ(b.sun_toward[2], glm::vec4(0.0f)) << "a sun of no direction points nowhere";
  EXPECT_EQ(b.sun_radiance[3], glm::vec4(0.0f)) << "past the suns the block is zero";
  EXPECT_EQ(b.fire_position[2], glm::vec4(2.0f, 4.0f, -2.0f, 2.5f));
  EXPECT_EQ(b.fire_intensity[2], glm::vec4(12.0f, 20.0f, 30.0f, 0.0f));
}

TEST(LightBlock, TakesAtMostTheShadersFireLightsAndRefusesTooManySuns) {
  const FireLights fire = fire_lights(kMaxFireLights + 3);
  EXPECT_EQ(pack_lights(SceneLighting{}, &fire).counts.y, kMaxFireLights);
  EXPECT_EQ(pack_lights(SceneLighting{}, nullptr).counts, glm::ivec4(1, 0, 0, 0)) << "the default sun";
  SceneLighting many;
  many.suns.assign(size_t(kMaxSuns) + 1, SunLight{});
  EXPECT_THROW(pack_lights(many, nullptr), std::invalid_argument);
  many.suns.pop_back();
  EXPECT_EQ(pack_lights(many, nullptr).counts.x, kMaxSuns);
}

// A compute shader that copies what lights.glsl reads, field by field, into a buffer laid out
// as LightBlock.
gpu::Program light_echo_program() {
  const std::string source = gpu::expand_includes(
      "#version 450 core\n"
      "layout(local_size_x = 1) in;\n"
      "#include \"lights.glsl\"\n"
      "layout(std430, binding = 3) writeonly buffer Echo { vec4 echo[]; };\n"
      "void main() {\n"
      "  echo[0] = vec4(ambient_light(), 0.0);\n"
      "  echo[1] = intBitsToFloat(ivec4(sun_count(), fire_light_count(), 0, 0));\n"
      "  for (int i = 0; i < 16; ++i) {\n"
      "    echo[2 + i] = vec4(toward_sun(i), 0.0);\n"
      "    echo[18 + i] = vec4(lights_sun_travel[i].xyz, 0.0);\n"
      "    echo[34 + i] = vec4(sun_radiance(i), 0.0);\n"
      "  }\n"
      "  for (int j = 0; j < 8; ++j) {\n"
      "    echo[50 + j] = lights_fire_position[j];\n"
      "    echo[58 + j] = vec4(lights_fire_intensity[j].rgb, 0.0);\n"
      "  }\n"
      "}\n",
      "light_echo.comp");
  return gpu::link_program({{GL_COMPUTE_SHADER, "light_echo.comp", source}});
}

TEST(LightBlock, ShadersReadTheBlockAsTheEngineWritesIt) {
  shared_headless_context().make_current();
  const FireLights fire = fire_lights(5);
  const LightBlock block = pack_lights(three_suns(), &fire);
  LightBuffer buffer;
  buffer.upload(block);
  buffer.bind();
  gpu::Program program = light_echo_program();
  gpu::Buffer echo = gpu::make_buffer();
  glNamedBufferData(echo.get(), sizeof(LightBlock), nullptr, GL_DYNAMIC_READ);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, echo.get());
  glUseProgram(program.get());
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  LightBlock read{};
  glGetNamedBufferSubData(echo.get(), 0, sizeof(LightBlock), &read);
  glUseProgram(0);
  EXPECT_EQ(read.counts, block.counts);
  EXPECT_EQ(read.ambient, block.ambient);
  for (int i = 0; i < kMaxSuns; ++i) {
    EXPECT_EQ(read.sun_toward[i], block.sun_toward[i]) << i;
    EXPECT_EQ(read.sun_travel[i], block.sun_travel[i]) << i;
    EXPECT_EQ(read.sun_radiance[i], block.sun_radiance[i]) << i;
  }
  for (int j = 0; j < kMaxFireLights; ++j) {
    EXPECT_EQ(read.fire_position[j], block.fire_position[j]) << j;
    EXPECT_EQ(read.fire_intensity[j], block.fire_intensity[j]) << j;
  }
}

}  // namespace
}  // namespace pyro
