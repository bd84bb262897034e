#include "systems/composite/compose_tiles.h"

#include <stdexcept>
#include <string>

#include "engine/gpu/shader_program.h"
#include "systems/composite/particle_depth_grid.h"

namespace pyro {

namespace {
constexpr int class_slots = 16;  // the buffer's counts: one per 4-bit class
constexpr GLsizeiptr count_bytes = class_slots * sizeof(GLuint);
}  // namespace

ComposeTiles::Grid ComposeTiles::grid_for(glm::ivec2 view, glm::ivec2 layer) {
  if (view.x <= 0 || view.y <= 0 || layer.x <= 0 || layer.y <= 0 || layer.x > view.x ||
      layer.y > view.y)
    throw std::invalid_argument("compose tiles: a layer of " + std::to_string(layer.x) + "x" +
                                std::to_string(layer.y) + " for a view of " +
                                std::to_string(view.x) + "x" + std::to_string(view.y) +
                                " (expected a non-empty layer no larger than the view)");
  Grid g;
  g.view = view;
  g.texels_per_pixel = glm::vec2(layer) / glm::vec2(view);
  g.tiles = (view + tile_pixels - 1) / tile_pixels;
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
  glUniform1i(loc("u_tile_pixels"), tile_pixels);
  glUniform2i(loc("u_view_size"), grid.view.x, grid.view.y);
  glUniform2f(loc("u_texels_per_pixel"), grid.texels_per_pixel.x, grid.texels_per_pixel.y);
  if (how.edges) {
    glUniform2f(loc("u_inverse_depth"), how.inverse_depth.x, how.inverse_depth.y);
    glUniform1i(loc("u_depth_cell"), ParticleDepthGrid::cell_pixels);
  }
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, lists_[s].get());
  glDispatchCompute(static_cast<GLuint>((grid.tiles.x + 7) / 8), static_cast<GLuint>((grid.tiles.y + 7) / 8), 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void ComposeTiles::draw(GLuint program, const Grid& grid, unsigned cls, int slot,
                        glm::ivec2 origin) {
  const size_t s = static_cast<size_t>(slot);
  auto loc = [&](const char* name) { return glGetUniformLocation(program, name); };
  glUniform1i(loc("u_class"), static_cast<GLint>(cls));
  glUniform1i(loc("u_tile_count"), capacity_[s]);
  glUniform1i(loc("u_tile_pixels"), tile_pixels);
  glUniform2i(loc("u_tiles"), grid.tiles.x, grid.tiles.y);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, lists_[s].get());
  // The viewport spans whole tiles, so that every tile's centre (the point's vertex, which
  // decides whether a point is clipped) lies inside it; the scissor keeps the view's pixels.
  glViewport(origin.x, origin.y, grid.tiles.x * tile_pixels, grid.tiles.y * tile_pixels);
  glScissor(origin.x, origin.y, grid.view.x, grid.view.y);
  glEnable(GL_SCISSOR_TEST);
  glEnable(GL_PROGRAM_POINT_SIZE);
  glDrawArrays(GL_POINTS, 0, grid.count());
  glDisable(GL_PROGRAM_POINT_SIZE);
  glDisable(GL_SCISSOR_TEST);
  glViewport(origin.x, origin.y, grid.view.x, grid.view.y);
}

}  // namespace pyro
