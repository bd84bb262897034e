#version 450 core
// The tiles of one class of the final pass (compose_tiles.comp says what a tile is): six vertices
// (two triangles) per entry of the class's list, up to the list's length; the vertices past it
// are put outside the view. A tile's quad lies between its pixel edges (k B + 1/2) / s, the first
// and last tiles reaching the viewport's borders, so that the tiles cover every pixel once.
// (Not an instanced or indirect draw: llvmpipe runs those instance by instance, or flushes.)
layout(std430, binding = 0) readonly buffer TileLists {
  uint counts[8];
  uint tiles[];
};

uniform int u_class;              // whose list this draw reads
uniform int u_tile_count;
uniform ivec2 u_tiles;
uniform int u_tile_texels;        // B
uniform vec2 u_texels_per_pixel;  // s
uniform vec2 u_view_size;         // pixels

void main() {
  int index = gl_VertexID / 6;  // the tile's place in the list; 6 vertices, two triangles
  int vertex = gl_VertexID % 6;
  if (uint(index) >= counts[u_class]) {  // past the class's list
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // outside the view: clipped away
    return;
  }
  uint code = tiles[u_class * u_tile_count + index];
  ivec2 tile = ivec2(int(code & 0xffffu), int(code >> 16));
  const ivec2 corners[6] = ivec2[6](ivec2(0, 0), ivec2(1, 0), ivec2(0, 1),
                                    ivec2(0, 1), ivec2(1, 0), ivec2(1, 1));
  ivec2 k = tile + corners[vertex];
  vec2 edge = (vec2(k * u_tile_texels) + 0.5) / u_texels_per_pixel;
  edge = mix(edge, vec2(0.0), equal(k, ivec2(0)));
  edge = mix(edge, u_view_size, equal(k, u_tiles));
  gl_Position = vec4(edge / u_view_size * 2.0 - 1.0, 0.0, 1.0);
}
