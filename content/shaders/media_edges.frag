#version 450 core
// The layer texels on a depth edge the particles can see (depth-aware upsampling), at layer size
// after media_prepare.frag, for compose_tiles.comp to find with one gather per 2 x 2 texels: 1 at
// texel t when along x or y
//   - the second difference of the texels' 1/z exceeds u_depth_tolerance times t's (u = 1/z is
//     affine on a plane, so a slope is no edge however steep; a silhouette is a jump), and
//   - the three texels' clip depths (1/z clamped to the depths the particles reach at t,
//     systems/composite/particle_depth_grid.h) differ by more than u_depth_tolerance times that
//     range: compose.frag's own test (a horizon behind the particles clamps alike);
// else 0. The neighbours beyond the layer's border are the border texels (clamp to edge).
layout(binding = 0) uniform sampler2D u_media_depth;      // media_prepare.frag's: 1/z in r
layout(binding = 1) uniform sampler2D u_particle_depths;  // compose.frag says what they are
uniform vec2 u_scale;     // full-size pixels per layer texel
uniform int u_depth_cell;  // the particle depths' cells in pixels
uniform float u_depth_tolerance;

layout(location = 0) out vec4 o_edge;

void main() {
  ivec2 t = ivec2(gl_FragCoord.xy);
  vec2 texel = 1.0 / vec2(textureSize(u_media_depth, 0));
  // The 2 x 2 blocks from t - (1, 1) and from t: (x, y, z, w) = (i0, j1), (i1, j1), (i1, j0),
  // (i0, j0), so below.x = u(t - x), below.z = u(t - y), above.x = u(t + y), above.z = u(t + x).
  vec4 below = textureGather(u_media_depth, vec2(t) * texel, 0);
  vec4 above = textureGather(u_media_depth, (vec2(t) + 1.0) * texel, 0);
  float u = below.y;
  vec2 a = below.xz, b = above.zx;
  vec2 second = abs(a + b - 2.0 * u);
  ivec2 cell = ivec2((vec2(t) + 0.5) * u_scale) / u_depth_cell;
  vec2 range = texelFetch(u_particle_depths, cell, 0).rg;  // 1/z: far, near
  vec2 ca = clamp(a, range.x, range.y), cb = clamp(b, range.x, range.y);
  float cu = clamp(u, range.x, range.y);
  vec2 apart = max(abs(ca - cu), abs(cb - cu));
  float seen = u_depth_tolerance * (range.y - range.x);
  bool edge = (second.x > u_depth_tolerance * u && apart.x > seen) ||
              (second.y > u_depth_tolerance * u && apart.y > seen);
  o_edge = vec4(edge ? 1.0 : 0.0);
}
