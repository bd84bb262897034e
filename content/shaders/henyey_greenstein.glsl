// Henyey & Greenstein 1941, per steradian, its integral over the sphere 1 (engine/math/
// phase_function.h, henyey_greenstein): p(mu) = (1 - g^2) / (4 pi (1 + g^2 - 2 g mu)^(3/2)),
// mu the cosine between the light's way before and after scattering.
float henyey_greenstein(float mu, float g) {
  float k = 1.0 + g * g - 2.0 * g * mu;
  return (1.0 - g * g) / (12.566370614359172 * k * sqrt(k));
}
