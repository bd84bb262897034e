#version 450 core
// Glyph coverage (0 or 1, R8 atlas, nearest texel) times the colour's alpha.
layout(binding = 0) uniform sampler2D u_atlas;
in vec2 v_texel;
flat in vec4 v_color;
out vec4 o_color;

void main() {
  float coverage = texelFetch(u_atlas, ivec2(v_texel), 0).r;
  o_color = vec4(v_color.rgb, v_color.a * coverage);
}
