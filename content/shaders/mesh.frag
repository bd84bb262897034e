#version 450 core
// Lambertian surface under one directional light plus ambient light, in linear RGB.
in vec3 v_normal;

uniform vec3 u_albedo;
uniform vec3 u_light_direction;  // unit, the direction light travels
uniform vec3 u_light_color;
uniform vec3 u_ambient;

layout(location = 0) out vec4 o_color;

void main() {
  vec3 n = normalize(v_normal);
  if (!gl_FrontFacing) n = -n;
  float lambert = max(dot(n, -u_light_direction), 0.0);
  o_color = vec4(u_albedo * (u_ambient + u_light_color * lambert), 1.0);
}
