#version 450 core
// Explosion media at layer size, before the full-size pass (Umenhoffer et al. 2006, section 4):
// dust, then fire, then smoke composited over each other (premultiplied "over": the result over
// the scene equals the three composited in turn), and 1/z of the view depth z each layer texel
// was rendered against (the full-size depth at its representative pixel floor((t + 1/2) s), as
// the spherical-billboard shader fetched it) with the fire's opacity, and the heat shimmer's scene
// offset (fire opacity times the shimmer noise at this texel), so the full-size pass reads them
// in one fetch.
layout(binding = 0) uniform sampler2D u_media;  // dust, smoke, fire cells side by side
uniform int u_cell_width;
layout(binding = 3) uniform sampler2D u_scene_depth;  // full size, window depth
uniform vec2 u_scale;  // full-size pixels per layer texel
uniform float u_near;
uniform float u_far;
layout(binding = 4) uniform sampler2D u_shimmer_noise;  // compose.frag says what it is
uniform float u_shimmer;         // scene offset (fraction of the view) per unit fire opacity
uniform float u_shimmer_tiling;  // noise periods across the view

layout(location = 0) out vec4 o_combined;
layout(location = 1) out vec4 o_depth_fire;

void main() {
  ivec2 t = ivec2(gl_FragCoord.xy);
  vec4 d = texelFetch(u_media, t, 0);
  vec4 s = texelFetch(u_media, t + ivec2(u_cell_width, 0), 0);
  vec4 f = texelFetch(u_media, t + ivec2(2 * u_cell_width, 0), 0);
  o_combined = s + (f + d * (1.0 - f.a)) * (1.0 - s.a);
  ivec2 at = min(ivec2((vec2(t) + 0.5) * u_scale), textureSize(u_scene_depth, 0) - 1);
  float z_ndc = texelFetch(u_scene_depth, at, 0).r * 2.0 - 1.0;
  float inverse_view = (u_far + u_near - z_ndc * (u_far - u_near)) / (2.0 * u_near * u_far);
  vec2 uv = (vec2(t) + 0.5) / vec2(u_cell_width, textureSize(u_media, 0).y);
  vec2 offset = (textureLod(u_shimmer_noise, uv * u_shimmer_tiling, 0.0).rg * 2.0 - 1.0) * (u_shimmer * f.a);
  o_depth_fire = vec4(inverse_view, f.a, offset);
}
