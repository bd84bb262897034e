#pragma once
// A random scalar for emitters: a constant, uniform in [min, max], or normal (mean, stddev)
// clamped to [min, max]. Sampled by sample_distribution (systems/emitter/emitter_sampling.h).
namespace pyro {

enum class DistributionKind { constant, uniform, normal };

struct Distribution {
  DistributionKind kind = DistributionKind::constant;
  float value = 0.0f;               // constant
  float min = 0.0f, max = 0.0f;     // uniform range; the clamp of a normal
  float mean = 0.0f, stddev = 0.0f; // normal

  static Distribution constant(float v) { return {DistributionKind::constant, v, v, v, v, 0.0f}; }
  static Distribution uniform(float lo, float hi) {
    return {DistributionKind::uniform, 0.5f * (lo + hi), lo, hi, 0.5f * (lo + hi), 0.0f};
  }
  static Distribution normal(float mean, float stddev, float lo, float hi) {
    return {DistributionKind::normal, mean, lo, hi, mean, stddev};
  }
};

}  // namespace pyro
