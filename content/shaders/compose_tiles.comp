#version 450 core
// Sorts the final pass's screen tiles by the work their pixels need (systems/composite/
// compose_tiles.h), so that compose.frag's costly variants run only where they change the result:
// on llvmpipe a fragment shader pays for every instruction on every pixel (branches included),
// so the only way to skip work per pixel is to not rasterise it.
//
// A tile is a square of P x P pixels from the view's lower-left corner (the last column and row
// may reach past the view). It reads, by bilinear filtering or a nearest texel at layer
// coordinate (p + 1/2) s - 1/2 (s the layer texels per pixel), the layer texels from
// floor((p0 + 1/2) s - 1/2) to floor((p1 + 1/2) s - 1/2) + 1 for its pixels p0..p1; over those
// (one more on every side, against rounding) it finds:
//   media  any premultiplied media: an alpha above 0 (rgb is 0 where alpha is 0). Without, the
//          pixels show the scene alone: exact;
//   fire   any fire opacity above 0: the shimmer's offset (opacity times noise) is not 0.
//          Without, the scene is read unshifted: exact;
//   edge   a texel media_edges.frag marked: a depth edge in the layer that the particles can
//          see. Where there is none, compose.frag's depth-aware test keeps the bilinear
//          sample at every pixel whose surface the texels saw, but for
//   front  a cell of the tile's pixels (systems/composite/particle_depth_grid.h) whose nearest
//          opaque surface (cell_nearest_depth.comp) is nearer than every particle that reaches
//          it: geometry thinner than a texel, which no texel saw, may stand there. compose.frag's
//          FRONT variant gives such pixels no media and the others the bilinear sample, as its
//          depth-aware variant does. Only without edge.
// The class is media | edge << 1 | fire << 2 | front << 3, or 0 (the scene alone) without media;
// each tile is appended to its class's list, and counts[c] is the list's length.
layout(local_size_x = 8, local_size_y = 8) in;

#ifndef USE_LEFT
#define USE_LEFT 1
#endif
#ifndef USE_RIGHT
#define USE_RIGHT 0
#endif
#ifndef EDGES
#define EDGES 1  // depth-aware upsampling on: classify depth edges
#endif
#ifndef FIRE
#define FIRE 1  // heat shimmer on: classify tiles with fire
#endif

// The units compose.frag reads (Compositor::bind_views).
layout(binding = 6) uniform sampler2D u_left_media;         // layer size, premultiplied
layout(binding = 7) uniform sampler2D u_left_media_depth;   // 1/z, fire opacity, offset
layout(binding = 9) uniform sampler2D u_right_media;
layout(binding = 10) uniform sampler2D u_right_media_depth;
layout(binding = 13) uniform sampler2D u_left_media_edges;  // media_edges.frag's marks
layout(binding = 14) uniform sampler2D u_right_media_edges;
layout(binding = 11) uniform sampler2D u_left_particle_depths;  // per cell, 1/z: far, near
layout(binding = 12) uniform sampler2D u_right_particle_depths;
layout(binding = 15) uniform sampler2D u_left_cell_nearest;     // per cell, window depth
layout(binding = 16) uniform sampler2D u_right_cell_nearest;
#include "inverse_depth.glsl"
uniform int u_depth_cell;      // the cells' size in pixels

layout(std430, binding = 0) buffer TileLists {
  uint counts[16];  // per class c: the length of its list
  uint tiles[];       // class c's tiles from c * u_tile_count on, packed x | y << 16
};

uniform ivec2 u_tiles;            // tiles across and up
uniform int u_tile_count;         // u_tiles.x * u_tiles.y
uniform int u_tile_pixels;        // P
uniform ivec2 u_view_size;        // pixels
uniform vec2 u_texels_per_pixel;  // s, at most 1

float max4(vec4 v) { return max(max(v.x, v.y), max(v.z, v.w)); }

// textureGather's 2x2 block with lower-left texel b: uv at the block's centre. b is kept inside so
// that the last texel is read in a block and no texel outside.
vec2 block_uv(ivec2 b, ivec2 size) {
  return (vec2(min(b, max(size - 2, ivec2(0)))) + 1.0) / vec2(size);
}

// Whether a cell of pixels p0..p1 holds a surface nearer than every particle that reaches it
// (a cell no particle reaches holds one value and counts as none).
bool front_in(sampler2D particle_depths, sampler2D cell_nearest, ivec2 p0, ivec2 p1) {
  ivec2 c0 = p0 / u_depth_cell, c1 = p1 / u_depth_cell;
  for (int y = c0.y; y <= c1.y; ++y)
    for (int x = c0.x; x <= c1.x; ++x) {
      vec2 range = texelFetch(particle_depths, ivec2(x, y), 0).rg;
      float u = inverse_depth(texelFetch(cell_nearest, ivec2(x, y), 0).r);
      if (range.y > range.x && u > range.y) return true;
    }
  return false;
}

uint eye_class(sampler2D media, sampler2D media_depth, sampler2D media_edges,
               sampler2D particle_depths, sampler2D cell_nearest, ivec2 tile) {
  ivec2 layer = textureSize(media, 0);
  ivec2 p0 = tile * u_tile_pixels;
  ivec2 p1 = min(p0 + u_tile_pixels, u_view_size) - 1;
  ivec2 lo = ivec2(floor((vec2(p0) + 0.5) * u_texels_per_pixel - 0.5));
  ivec2 hi = ivec2(floor((vec2(p1) + 0.5) * u_texels_per_pixel - 0.5)) + 1;
  ivec2 t0 = clamp(lo - 1, ivec2(0), layer - 1);
  ivec2 t1 = clamp(hi + 1, ivec2(0), layer - 1);
  float alpha = 0.0, fire = 0.0, edge_mark = 0.0;
  for (int y = t0.y; y <= t1.y; y += 2) {
    for (int x = t0.x; x <= t1.x; x += 2) {
      vec2 uv = block_uv(ivec2(x, y), layer);
      alpha = max(alpha, max4(textureGather(media, uv, 3)));
#if FIRE
      fire = max(fire, max4(textureGather(media_depth, uv, 1)));
#endif
#if EDGES
      edge_mark = max(edge_mark, max4(textureGather(media_edges, uv, 0)));
#endif
    }
  }
  bool edge = edge_mark > 0.0;
  if (alpha <= 0.0) return 0u;
  uint c = 1u;
  if (edge) c |= 2u;
  if (fire > 0.0) c |= 4u;
#if EDGES
  if (!edge && front_in(particle_depths, cell_nearest, p0, p1)) c |= 8u;
#endif
  return c;
}

void main() {
  ivec2 tile = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(tile, u_tiles))) return;
  uint c = 0u;
#if USE_LEFT
  c |= eye_class(u_left_media, u_left_media_depth, u_left_media_edges, u_left_particle_depths,
                 u_left_cell_nearest, tile);
#endif
#if USE_RIGHT
  c |= eye_class(u_right_media, u_right_media_depth, u_right_media_edges,
                 u_right_particle_depths, u_right_cell_nearest, tile);
#endif
  if ((c & 2u) != 0u) c &= ~8u;  // the depth-aware variant covers the front test
  uint slot = atomicAdd(counts[c], 1u);
  tiles[int(c) * u_tile_count + int(slot)] = uint(tile.x) | uint(tile.y) << 16;
}
