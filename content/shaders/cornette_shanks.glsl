// Cornette & Shanks 1992, eq. 8: Umenhoffer et al. 2006's section 3.1 phase function
// (engine/math/phase_function.h says why it is not Henyey-Greenstein), per steradian, its
// integral over the sphere 1:
// p(mu) = 3/(8 pi) (1 - g^2) (1 + mu^2) / ((2 + g^2) (1 + g^2 - 2 g mu)^(3/2)).
// In closed form rather than the paper's (mu, g) texture: exact, and cheaper than a filtered
// fetch on a CPU rasteriser.
float cornette_shanks(float mu, float g) {
  const float pi = 3.14159265358979;
  float g2 = g * g;
  float k = 1.0 + g2 - 2.0 * g * mu;
  return 3.0 / (8.0 * pi) * (1.0 - g2) * (1.0 + mu * mu) / ((2.0 + g2) * k * sqrt(k));
}
