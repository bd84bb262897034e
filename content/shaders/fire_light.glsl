// One point light of the explosion's fire (components/fire_lights.h) at position.xyz (view
// space), of radius position.w and intensity I, as radiance scattered at x toward the eye
// (to_eye, unit) by a medium of phase-function parameter g, before the albedo:
//   I / max(|x - p|^2, r^2) P(mu),  mu the cosine between the light's way and to_eye.
// The same law as engine/math/point_light_clusters.h's point_irradiance (which the clusters and
// their tests use), times the phase function. Needs cornette_shanks.glsl.
vec3 fire_light_inscattered(vec4 position, vec3 intensity, vec3 x, vec3 to_eye, float g) {
  vec3 travel = x - position.xyz;  // the light's way from the source to x
  float d2 = dot(travel, travel);
  float mu = d2 > 0.0 ? dot(travel, to_eye) * inversesqrt(d2) : 0.0;
  return intensity / max(d2, position.w * position.w) * cornette_shanks(mu, g);
}
