// Linear radiance to the display's [0, 1] without a hue shift (engine/math/highlight_rolloff.h,
// which explains it): below 1 unchanged; a colour whose largest channel m exceeds 1 becomes
// c / m² + (1 − 1/m): its HSV hue kept, its largest channel 1, whiter as m grows.
vec3 roll_off_highlights(vec3 c) {
  c = max(c, vec3(0.0));
  float m = max(c.r, max(c.g, c.b));
  return m <= 1.0 ? c : c / (m * m) + vec3(1.0 - 1.0 / m);
}
