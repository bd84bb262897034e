#include "systems/composite/compose_tiles.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "engine/gpu/shader_program.h"

namespace pyro {

namespace {
constexpr int class_slots = 8;  // the buffer's counts: one per 3-bit class
constexpr GLsizeiptr count_bytes = class_slots * sizeof(GLuint);
}  // namespace

ComposeTiles::Grid ComposeTiles::grid_for(glm::ivec2 view, glm::ivec2 layer) {
  Grid g;
  g.texels_per_pixel = glm::vec2(layer) / glm::vec2(view);
  g.tile_texels = std::max(1, static_cast<int>(std::lround(16.0 * g.texels_per_pixel.x)));
  g.tiles = (layer + g.tile_texels - 1) / g.tile_texels;
  return g;
}

void ComposeTiles::classify(const Grid& grid, const Classify& how, int slot) {
  const size_t s = static_cast<size_t>(slot);
  if (capacity_[s] < grid.count()) {
    lists_[s] = gpu::make_buffer();
    capacity_[s] = grid.count();
    glNamedBufferStorage(lists_[s].get(),
                         count_bytes + GLsizeiptr(class_slots) * capacity_[s] * sizeof(GLuint),
                         nullptr, GL_DYNAMIC_STORAGE_BIT);
  }
  // Every class's list empty.
  const std::array<GLuint, class_slots> counts{};
  glNamedBufferSubData(lists_[s].get(), 0, count_bytes, counts.data());

  const size_t key = size_t(how.use_left) | size_t(how.use_right) << 1 | size_t(how.edges) << 2 |
                     size_t(how.fire) << 3;
  gpu::Program& p = programs_[key];
  if (p.get() == 0) {
    auto flag = [](const char* name, bool on) { return std::string(name) + (on ? " 1" : " 0"); };
    p = gpu::load_compute_program("compose_tiles.comp",
                                  {flag("USE_LEFT", how.use_left), flag("USE_RIGHT", how.use_right),
                                   flag("EDGES", how.edges), flag("FIRE", how.fire)});
  }
  glUseProgram(p.get());
  auto loc = [&](const char* name) { return gpu::uniform_location(p, name); };
  glUniform2i(loc("u_tiles"), grid.tiles.x, grid.tiles.y);
  glUniform1i(loc("u_tile_count"), capacity_[s]);
  glUniform1i(loc("u_tile_texels"), grid.tile_texels);
  glUniform1f(loc("u_depth_tolerance"), how.depth_tolerance);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, lists_[s].get());
  glDispatchCompute(static_cast<GLuint>((grid.tiles.x + 7) / 8), static_cast<GLuint>((grid.tiles.y + 7) / 8), 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void ComposeTiles::draw(GLuint program, const Grid& grid, unsigned cls, int slot) {
  const size_t s = static_cast<size_t>(slot);
  auto loc = [&](const char* name) { return glGetUniformLocation(program, name); };
  glUniform1i(loc("u_class"), static_cast<GLint>(cls));
  glUniform1i(loc("u_tile_count"), capacity_[s]);
  glUniform2i(loc("u_tiles"), grid.tiles.x, grid.tiles.y);
  glUniform1i(loc("u_tile_texels"), grid.tile_texels);
  glUniform2f(loc("u_texels_per_pixel"), grid.texels_per_pixel.x, grid.texels_per_pixel.y);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, lists_[s].get());
  glDrawArrays(GL_TRIANGLES, 0, 6 * grid.count());
}

}  // namespace pyro
