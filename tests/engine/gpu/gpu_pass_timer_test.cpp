// GpuPassTimer on the headless context: fragments counted by GL_SAMPLES_PASSED equal the pixels a
// scissored full-screen draw covers (a closed form), nested passes lie inside their outer pass on
// the GPU timeline one after the other, and query objects are reused between collections.
#include <gtest/gtest.h>

#include <chrono>

#include "engine/gpu/gpu_pass_timer.h"
#include "engine/gpu/render_target.h"
#include "engine/gpu/shader_program.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"

namespace pyro {
namespace {

gpu::Program constant_colour_program() {
  // One triangle covering the viewport (gl_VertexID 0, 1, 2 -> (-1,-1), (3,-1), (-1,3)).
  const std::string vs =
      "#version 450 core\n"
      "void main() { vec2 p = vec2((gl_VertexID & 1) * 4 - 1, (gl_VertexID >> 1) * 4 - 1);\n"
      "  gl_Position = vec4(p, 0.0, 1.0); }\n";
  const std::string fs =
      "#version 450 core\nout vec4 colour;\nvoid main() { colour = vec4(1.0, 0.5, 0.25, 1.0); }\n";
  return gpu::link_program({{GL_VERTEX_SHADER, "test.vert", vs}, {GL_FRAGMENT_SHADER, "test.frag", fs}});
}

TEST(GpuPassTimer, CountsTheFragmentsOfAScissoredDrawAndNestsPasses) {
  shared_headless_context().make_current();
  const int w = 64, h = 48;
  gpu::RenderTarget target(w, h, GL_RGBA16F);
  gpu::Program program = constant_colour_program();
  gpu::VertexArray vao = gpu::make_vertex_array();
  gpu::GpuPassTimer timer(std::chrono::steady_clock::now());
  gpu::set_active_gpu_pass_timer(&timer);
  for (int frame = 0; frame < 3; ++frame) {
    timer.begin_frame(static_cast<uint64_t>(frame));
    {
      const gpu::GpuPassScope outer("outer");
      target.bind();
      glDisable(GL_DEPTH_TEST);
      glEnable(GL_SCISSOR_TEST);
      glUseProgram(program.get());
      glBindVertexArray(vao.get());
      {
        const gpu::GpuPassScope inner("left half", true);
        glScissor(0, 0, w / 2, h);
        glDrawArrays(GL_TRIANGLES, 0, 3);
      }
      {
        const gpu::GpuPassScope inner("top 10 rows twice", true);
        glScissor(0, h - 10, w, 10);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glDrawArrays(GL_TRIANGLES, 0, 3);
      }
      glDisable(GL_SCISSOR_TEST);
      glEnable(GL_DEPTH_TEST);
      glBindVertexArray(0);
    }
    glFinish();
    const std::vector<gpu::GpuPassSample> samples = timer.collect();
    ASSERT_EQ(samples.size(), 3u);
    EXPECT_EQ(samples[0].name, "outer");
    EXPECT_EQ(samples[0].fragments, -1);
    EXPECT_EQ(samples[1].fragments, int64_t(w / 2) * h);
    EXPECT_EQ(samples[2].fragments, int64_t(2) * w * 10);
    for (const auto& s : samples) EXPECT_EQ(s.frame, uint64_t(frame));
    for (size_t i = 1; i < 3; ++i) {
      EXPECT_GE(samples[i].start_us, samples[0].start_us);
      EXPECT_LE(samples[i].start_us + samples[i].duration_us,
                samples[0].start_us + samples[0].duration_us + 1e-3);
    }
    // The two inner passes ran one after the other: the second starts where the first ended.
    EXPECT_GE(samples[2].start_us, samples[1].start_us + samples[1].duration_us - 1e-3);
    // The outer pass holds both inner passes' work, so it lasts at least as long as both.
    EXPECT_GE(samples[0].duration_us + 1e-3, samples[1].duration_us + samples[2].duration_us);
  }
  gpu::set_active_gpu_pass_timer(nullptr);
  EXPECT_TRUE(timer.collect().empty());
}

TEST(GpuPassTimer, ScopesDoNothingWithoutAnActiveTimer) {
  shared_headless_context().make_current();
  ASSERT_EQ(gpu::active_gpu_pass_timer(), nullptr);
  const gpu::GpuPassScope scope("nobody listens", true);  // must not touch GL queries
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace pyro
