#version 450 core
// One flame frame, colour scaled by the billboard's intensity and brought within 1, as the
// thesis' fixed-point framebuffer needs (section 4.3): rolled off keeping its hue
// (highlight_rolloff.glsl), not clipped per channel, which would turn a brightened orange
// yellow. The blend itself is fixed-function: (1 - dst, 1) or (src alpha, 1 - src alpha),
// chosen per fire.
in vec3 v_uv_layer;
in float v_intensity;

uniform sampler2DArray u_frames;  // sRGB texels, read as linear

#include "highlight_rolloff.glsl"

layout(location = 0) out vec4 o_color;

void main() {
  vec4 t = texture(u_frames, v_uv_layer);
  o_color = vec4(roll_off_highlights(t.rgb * v_intensity), t.a);
}
