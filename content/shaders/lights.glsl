// Every light of the frame (components/light_block.h, bound by each renderer at binding 0): the
// directional lights (suns; the first, the key light, casts the shadows), the ambient term and
// the fire's clustered point lights, in world space. Every shader that lights reads them here.
layout(std140, binding = 0) uniform Lights {
  vec4 lights_ambient;              // rgb
  ivec4 lights_counts;              // x: suns, y: fire lights
  vec4 lights_sun_toward[16];       // xyz: unit, toward the light
  vec4 lights_sun_travel[16];       // xyz: the way it travels, as the scene gives it (not unit)
  vec4 lights_sun_radiance[16];     // rgb: colour times intensity
  vec4 lights_fire_position[8];     // xyz: place; w: radius
  vec4 lights_fire_intensity[8];    // rgb: per steradian
};

vec3 ambient_light() { return lights_ambient.rgb; }
int sun_count() { return lights_counts.x; }
vec3 toward_sun(int i) { return lights_sun_toward[i].xyz; }
vec3 sun_radiance(int i) { return lights_sun_radiance[i].rgb; }
// The key light (the first sun; black, from straight above, when the scene has none).
vec3 key_toward() { return lights_counts.x > 0 ? lights_sun_toward[0].xyz : vec3(0.0, 1.0, 0.0); }
vec3 key_radiance() { return lights_counts.x > 0 ? lights_sun_radiance[0].rgb : vec3(0.0); }
int fire_light_count() { return lights_counts.y; }

// The way the key light travels in the space of `view` (a camera's view matrix), unit (straight
// down without a key light): rotated as the scene gives it, then normalised, each sum and product
// in the order of the CPU's maths (glm) and unfused (precise), so that both give the same bits.
vec3 key_travel_in(mat4 view) {
  vec3 t = lights_counts.x > 0 ? lights_sun_travel[0].xyz : vec3(0.0, -1.0, 0.0);
  precise vec4 a = view[0] * t.x + view[1] * t.y;
  precise vec4 b = view[2] * t.z + view[3] * 0.0;
  precise vec3 v = (a + b).xyz;
  precise float length2 = v.x * v.x + v.y * v.y;
  length2 = length2 + v.z * v.z;
  precise float inverse_length = 1.0 / sqrt(length2);
  return v * inverse_length;
}

// The fire-light law (engine/math/point_light_clusters.h, point_irradiance): fire light j, of
// intensity I and radius r at p, lights x with I w / max(|x - p|^2, r^2), w the receiver's weight
// for light travelling p -> x (its phase function or its cosine; fire_light_cosine gives the
// cosine between that way and a unit vector).
struct FireLightPath {
  vec3 travel;  // x - p
  float d2;     // |x - p|^2
};
FireLightPath fire_light_path(int j, vec3 x) {
  vec3 travel = x - lights_fire_position[j].xyz;
  return FireLightPath(travel, dot(travel, travel));
}
float fire_light_cosine(FireLightPath path, vec3 unit) {
  return path.d2 > 0.0 ? dot(path.travel, unit) * inversesqrt(path.d2) : 0.0;
}
vec3 fire_light(int j, FireLightPath path, float weight) {
  float r = lights_fire_position[j].w;
  return lights_fire_intensity[j].rgb * weight / max(path.d2, r * r);
}
