#pragma once
// Screen tiles of the final pass, sorted by the work their pixels need, so that compose.frag's
// costly variants (depth-aware upsampling, heat shimmer) run only where they change the image.
// On llvmpipe a fragment shader pays for every instruction on every pixel, branches and discards
// included, so work is skipped per pixel only by not rasterising it: a compute pass
// (content/shaders/compose_tiles.comp, which says what decides a class) appends each tile to its
// class's list, and each class is drawn with its variant by one draw of point sprites, a tile
// each (content/shaders/compose_tile.vert): llvmpipe rasterises a point as one square, where a
// quad's two triangles cost a fifth more on its diagonal's blocks. Tiles without media or without
// fire give exactly the full variant's image; depth edges are found in the layer's depths and
// surfaces nearer than every particle per 8-pixel cell (the comp file says how), so the rest can
// differ only where the depth-aware test would reweight texels across an edge no texel saw:
// tests/systems/composite/compose_tiles_test.cpp bounds it.
#include <array>

#include <glm/vec2.hpp>

#include "engine/gpu/gl_objects.h"

namespace pyro {

class ComposeTiles {
 public:
  // Tile classes: media | edge << 1 | fire << 2 | front << 3, or 0 for the scene alone; front
  // (a surface nearer than every particle, no layer edge) only without edge, which covers it.
  static constexpr unsigned media = 1u, edge = 2u, fire = 4u, front = 8u;
  static constexpr std::array<unsigned, 7> classes = {
      0u, media, media | front, media | edge, media | fire, media | front | fire, media | edge | fire};

  // Square tiles of tile_pixels from the view's lower-left corner; the last column and row may
  // reach past the view (the draw scissors them to it). 32 was the fastest of 8 to 64 on
  // llvmpipe (docs/explosions.md): smaller tiles classify more finely, larger ones cost fewer
  // points.
  static constexpr int tile_pixels = 32;
  struct Grid {
    glm::ivec2 view{0};                  // pixels
    glm::vec2 texels_per_pixel{1.0f};    // s = layer size / view size, per axis (at most 1)
    glm::ivec2 tiles{0};                 // across and up
    int count() const { return tiles.x * tiles.y; }
  };
  // Throws std::invalid_argument for an empty view or a layer larger than the view.
  static Grid grid_for(glm::ivec2 view, glm::ivec2 layer);

  struct Classify {
    bool use_left = true, use_right = false;  // the views this draw reads (bound by the caller)
    bool edges = true;  // depth-aware upsampling: find the edges media_edges.frag marked, and fronts
    glm::vec2 inverse_depth{0.0f};  // with edges: inverse_depth.glsl's u_inverse_depth
    bool fire = true;   // heat shimmer: find fire
  };
  // Fills list set `slot` (0 or 1: the two views of a side-by-side frame) for `grid`, reading the
  // views' depth and media textures on compose.frag's units.
  void classify(const Grid& grid, const Classify& how, int slot);
  // Draws class `cls` of list set `slot` with `program` (a compose.frag variant linked with
  // compose_tile.vert, in use, its other uniforms set) into the view whose lower-left corner is
  // `origin` in the bound framebuffer. Leaves the viewport on the view, the scissor test off.
  void draw(GLuint program, const Grid& grid, unsigned cls, int slot, glm::ivec2 origin);

 private:
  std::array<gpu::Buffer, 2> lists_;
  std::array<int, 2> capacity_{0, 0};  // tiles per class each buffer holds
  std::array<gpu::Program, 16> programs_;
};

}  // namespace pyro
