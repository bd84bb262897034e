#version 450 core
// Per 8-pixel cell of a view (the cells of systems/composite/particle_depth_grid.h), the smallest
// window depth of the opaque scene in it: its nearest surface, which compose_tiles.comp compares
// with the nearest depth the cell's particles reach (its front class). Made again only when the
// opaque pass drew or restored the scene target (EyeTargets::opaque_version): once for a still
// camera.
layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D u_scene_depth;  // full size, window depth
layout(r32f, binding = 0) uniform writeonly image2D u_nearest;
uniform int u_cell;  // pixels a side

void main() {
  ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(cell, imageSize(u_nearest)))) return;
  ivec2 size = textureSize(u_scene_depth, 0);
  ivec2 p0 = cell * u_cell, p1 = min(p0 + u_cell, size) - 1;
  vec2 pixel = 1.0 / vec2(size);
  float d = 1.0;
  // Two by two pixels a gather; a block kept inside the view at its last column or row reads one
  // pixel of the cell before (a nearer depth there marks more texels: time, not the image).
  for (int y = p0.y; y <= p1.y; y += 2)
    for (int x = p0.x; x <= p1.x; x += 2) {
      ivec2 b = min(ivec2(x, y), max(size - 2, ivec2(0)));
      vec4 block = textureGather(u_scene_depth, (vec2(b) + 1.0) * pixel, 0);
      d = min(d, min(min(block.x, block.y), min(block.z, block.w)));
    }
  imageStore(u_nearest, cell, vec4(d));
}
