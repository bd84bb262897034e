#version 450 core
// One flame frame, colour scaled by the billboard's intensity (and clamped to 1, as the
// thesis' fixed-point framebuffer clamps: section 4.3). The blend itself is fixed-function:
// (1 - dst, 1) or (src alpha, 1 - src alpha), chosen per fire.
in vec3 v_uv_layer;
in float v_intensity;

uniform sampler2DArray u_frames;  // sRGB texels, read as linear

layout(location = 0) out vec4 o_color;

void main() {
  vec4 t = texture(u_frames, v_uv_layer);
  o_color = vec4(clamp(t.rgb * v_intensity, 0.0, 1.0), t.a);
}
