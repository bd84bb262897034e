#version 450 core
// Explosion media at layer size, before the full-size pass (Umenhoffer et al. 2006, section 4):
// dust, then fire, then smoke composited over each other (premultiplied "over": the result over
// the scene equals the three composited in turn), and the view depth each layer texel was
// rendered against (the full-size depth at its representative pixel floor((t + 1/2) s), as the
// spherical-billboard shader fetched it) with the fire's opacity for the heat shimmer.
layout(binding = 0) uniform sampler2D u_dust;
layout(binding = 1) uniform sampler2D u_smoke;
layout(binding = 2) uniform sampler2D u_fire;
layout(binding = 3) uniform sampler2D u_scene_depth;  // full size, window depth
uniform vec2 u_scale;  // full-size pixels per layer texel
uniform float u_near;
uniform float u_far;

layout(location = 0) out vec4 o_combined;
layout(location = 1) out vec4 o_depth_fire;

void main() {
  ivec2 t = ivec2(gl_FragCoord.xy);
  vec4 d = texelFetch(u_dust, t, 0);
  vec4 s = texelFetch(u_smoke, t, 0);
  vec4 f = texelFetch(u_fire, t, 0);
  o_combined = s + (f + d * (1.0 - f.a)) * (1.0 - s.a);
  ivec2 at = min(ivec2((vec2(t) + 0.5) * u_scale), textureSize(u_scene_depth, 0) - 1);
  float z_ndc = texelFetch(u_scene_depth, at, 0).r * 2.0 - 1.0;
  float view = 2.0 * u_near * u_far / (u_far + u_near - z_ndc * (u_far - u_near));
  o_depth_fire = vec4(view, f.a, 0.0, 1.0);
}
