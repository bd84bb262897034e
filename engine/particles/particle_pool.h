#pragma once
// Structure-of-arrays particle storage. Particles are many, short-lived and uniform, so they
// live in flat arrays (one per attribute) rather than as entities: simulation loops stay
// branch-free and vectorisable. Live particles occupy [0, size()); every array is sized to
// capacity() at construction and never reallocated, so pointers taken from them stay valid
// for the pool's lifetime.
//
// Writing fast loops over a pool: g++ cannot prove that px, vx, ... are distinct buffers, and a
// loop that stores to several arrays while reading several others needs more run-time alias
// checks than it will emit, so it silently stays scalar. Put `#pragma GCC ivdep` on the loop,
// or pass the arrays to a kernel as `float* __restrict` parameters (restrict on local
// variables is ignored), and build with -O3: -O2's cheap cost model vectorises neither.
#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace pyro {

struct ParticleInit {
  glm::vec3 position{0.0f};
  glm::vec3 velocity{0.0f};
  float radius = 1.0f;
  float density = 1.0f;
  glm::vec3 color{1.0f};
  float lifetime = std::numeric_limits<float>::infinity();
  float temperature = 0.0f;
  float opacity = 1.0f;       // multiplies density's effect; curves over life drive it
  uint8_t medium = 0;         // a ParticleMedium (components/particle_medium.h): dust, smoke, fire
  float age = 0.0f;           // seconds lived already (a stream's particle born within the step)
};

class ParticlePool {
 public:
  explicit ParticlePool(std::size_t capacity = 0) : capacity_(capacity) {
    for_each_array([&](auto& a) { a.resize(capacity); });
  }

  // Only [0, size()) is meaningful; the tail is scratch left by killed particles.
  std::vector<float> px, py, pz;
  std::vector<float> vx, vy, vz;
  std::vector<float> radius, density;
  std::vector<float> r, g, b;
  std::vector<float> age, lifetime, temperature;
  // Explosion media (systems/emitter, systems/animation): opacity in [0, 1] from the opacity
  // curve over life (1 when none); size0 the radius at birth (the size curve scales it);
  // medium a ParticleMedium, fire turning to smoke when it cools below its threshold.
  std::vector<float> opacity, size0;
  std::vector<uint8_t> medium;
  // Unique within the pool (until 2^32 spawns wrap it): a stable tie-breaker for sorting.
  std::vector<uint32_t> id;

  std::size_t size() const { return size_; }
  std::size_t capacity() const { return capacity_; }
  bool full() const { return size_ == capacity_; }
  bool empty() const { return size_ == 0; }
  // Spawns refused because the pool was full, over the pool's lifetime.
  uint64_t rejected() const { return rejected_; }
  uint32_t next_id() const { return next_id_; }

  // Appends a particle of age p.age; nullopt (and one more rejected()) if the pool is full.
  std::optional<std::size_t> spawn(const ParticleInit& p) {
    if (full()) {
      ++rejected_;
      return std::nullopt;
    }
    const std::size_t i = size_++;
    px[i] = p.position.x;
    py[i] = p.position.y;
    pz[i] = p.position.z;
    vx[i] = p.velocity.x;
    vy[i] = p.velocity.y;
    vz[i] = p.velocity.z;
    radius[i] = p.radius;
    density[i] = p.density;
    r[i] = p.color.x;
    g[i] = p.color.y;
    b[i] = p.color.z;
    age[i] = p.age;
    lifetime[i] = p.lifetime;
    temperature[i] = p.temperature;
    opacity[i] = p.opacity;
    size0[i] = p.radius;
    medium[i] = p.medium;
    id[i] = next_id_++;
    return i;
  }

  // Removes particle i by moving the last particle into its place (order not preserved).
  void kill(std::size_t i) {
    if (i >= size_)
      throw std::out_of_range("ParticlePool::kill: index " + std::to_string(i) + " >= size " +
                              std::to_string(size_));
    const std::size_t last = --size_;
    if (i != last) for_each_array([&](auto& a) { a[i] = a[last]; });
  }

  // Removes every particle i for which pred(i) is true; returns how many. pred is called once
  // per particle, in index order, and sees particle i as it was before the call (it may read
  // index i only: lower indices may already have been overwritten). Unlike kill(), this
  // keeps survivors in order, so a depth order sorted last frame stays nearly sorted.
  template <class Pred>
  std::size_t kill_if(Pred pred) {
    std::size_t w = 0;
    for (std::size_t i = 0; i < size_; ++i) {
      if (pred(i)) continue;
      if (w != i) for_each_array([&](auto& a) { a[w] = a[i]; });
      ++w;
    }
    const std::size_t killed = size_ - w;
    size_ = w;
    return killed;
  }

  // Removes all particles. Ids keep counting and rejected() keeps its total.
  void clear() { size_ = 0; }

  // Bytes one particle slot takes: the sum of the attribute arrays' elements.
  static std::size_t bytes_per_slot() {
    std::size_t bytes = 0;
    ParticlePool().for_each_array([&](const auto& a) { bytes += sizeof(a[0]); });
    return bytes;
  }

  // Applies f to every attribute array (16 float arrays, medium, then id), e.g. to permute
  // after a sort or to check that nothing reallocated.
  template <class F>
  void for_each_array(F&& f) {
    f(px), f(py), f(pz), f(vx), f(vy), f(vz), f(radius), f(density), f(r), f(g), f(b), f(age),
        f(lifetime), f(temperature), f(opacity), f(size0), f(medium), f(id);
  }
  template <class F>
  void for_each_array(F&& f) const {
    f(px), f(py), f(pz), f(vx), f(vy), f(vz), f(radius), f(density), f(r), f(g), f(b), f(age),
        f(lifetime), f(temperature), f(opacity), f(size0), f(medium), f(id);
  }

 private:
  std::size_t capacity_ = 0;
  std::size_t size_ = 0;
  uint64_t rejected_ = 0;
  uint32_t next_id_ = 0;
};

}  // namespace pyro
