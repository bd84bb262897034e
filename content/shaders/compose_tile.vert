#version 450 core
// The tiles of one class of the final pass (compose_tiles.comp says what a tile is): a point
// sprite per entry of the class's list, up to the list's length, of the tile's size and centred
// on it; the vertices past the list are put outside the view. The viewport spans whole tiles
// (ComposeTiles::draw), so every centre lies inside it, and the scissor trims the last column
// and row to the view. A point covers the pixels whose centres lie in [c - P/2, c + P/2) per axis:
// tile k's P pixels from k P.
// (Points, not quads: llvmpipe rasterises a point as one square; a quad's two triangles both
// shade the blocks on its diagonal. Not an instanced or indirect draw: llvmpipe runs those
// instance by instance, or flushes.)
layout(std430, binding = 0) readonly buffer TileLists {
  uint counts[16];
  uint tiles[];
};

uniform int u_class;        // whose list this draw reads
uniform int u_tile_count;   // the room per class's list
uniform ivec2 u_tiles;      // across and up: the viewport is u_tiles * P pixels
uniform int u_tile_pixels;  // P

void main() {
  gl_PointSize = float(u_tile_pixels);
  if (uint(gl_VertexID) >= counts[u_class]) {  // past the class's list
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // outside the view: clipped away
    return;
  }
  uint code = tiles[u_class * u_tile_count + gl_VertexID];
  vec2 centre = vec2(float(code & 0xffffu), float(code >> 16)) + 0.5;  // in tiles
  gl_Position = vec4(centre / vec2(u_tiles) * 2.0 - 1.0, 0.0, 1.0);
}
