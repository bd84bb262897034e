#version 450 core
// pyro view's overlay: glyph quads in window pixels (origin top left), texel coordinates into
// the glyph atlas (tools/pyro/viewer_text_renderer.cpp).
layout(location = 0) in vec2 a_pixel;
layout(location = 1) in vec2 a_texel;
layout(location = 2) in vec4 a_color;
uniform vec2 u_viewport;  // window size in pixels
out vec2 v_texel;
flat out vec4 v_color;

void main() {
  v_texel = a_texel;
  v_color = a_color;
  vec2 ndc = vec2(a_pixel.x / u_viewport.x * 2.0 - 1.0, 1.0 - a_pixel.y / u_viewport.y * 2.0);
  gl_Position = vec4(ndc, 0.0, 1.0);
}
