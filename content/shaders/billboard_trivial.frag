#version 450 core
// The benchmark's baseline: the same fragments with the cheapest shading that still blends,
// so that fill rate, not shading, is what it measures.
in vec2 v_texcoord;
flat in vec4 v_premultiplied;

layout(location = 0) out vec4 o_color;

void main() {
  o_color = vec4(0.01, 0.01, 0.01, 0.01);
}
