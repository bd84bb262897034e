#include "tools/bench/bench_ecs.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <vector>

#include "engine/ecs/schedule.h"
#include "engine/ecs/world.h"
#include "engine/particles/particle_pool.h"

namespace pyro {

namespace {

struct Position {
  float x, y, z;
};
struct Velocity {
  float x, y, z;
};

// Tells the compiler the memory behind p is read and written here, so the timed loop can
// neither be dropped nor moved across the clock reads.
inline void clobber(const void* p) { asm volatile("" : : "r"(p) : "memory"); }

template <class F>
double time_ns(F&& f) {
  using clock = std::chrono::steady_clock;
  clobber(nullptr);
  const auto t0 = clock::now();
  f();
  clobber(nullptr);
  const auto t1 = clock::now();
  return std::chrono::duration<double, std::nano>(t1 - t0).count();
}

double mean_of_middles(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

// Deterministic, varied inputs shared by all three methods (no RNG needed).
float init_value(std::size_t i, int axis) {
  return float(int((i * 2654435761u + unsigned(axis) * 40503u) % 2001u) - 1000) * 0.001f;
}

// The baseline's storage: six arrays, the loop GCC vectorises as it stands.
struct PlainArrays {
  explicit PlainArrays(std::size_t n) : x(n), y(n), z(n), vx(n), vy(n), vz(n) {
    for (std::size_t i = 0; i < n; ++i) {
      x[i] = init_value(i, 0), y[i] = init_value(i, 1), z[i] = init_value(i, 2);
      vx[i] = init_value(i, 3), vy[i] = init_value(i, 4), vz[i] = init_value(i, 5);
    }
  }
  void integrate(float dt) {
    float* px = x.data();
    float* py = y.data();
    float* pz = z.data();
    const float* pvx = vx.data();
    const float* pvy = vy.data();
    const float* pvz = vz.data();
#pragma GCC ivdep
    for (std::size_t i = 0; i < x.size(); ++i) {
      px[i] += pvx[i] * dt;
      py[i] += pvy[i] * dt;
      pz[i] += pvz[i] * dt;
    }
    clobber(px);
  }
  double sum() const {
    double s = 0;
    for (std::size_t i = 0; i < x.size(); ++i) s += double(x[i]) + y[i] + z[i];
    return s;
  }
  std::vector<float> x, y, z, vx, vy, vz;
};

ecs::World make_world(std::size_t n, std::vector<ecs::Entity>* handles = nullptr) {
  ecs::World world;
  world.group<Position, Velocity>();
  for (std::size_t i = 0; i < n; ++i) {
    const ecs::Entity e = world.create();
    world.emplace<Position>(e, Position{init_value(i, 0), init_value(i, 1), init_value(i, 2)});
    world.emplace<Velocity>(e, Velocity{init_value(i, 3), init_value(i, 4), init_value(i, 5)});
    if (handles) handles->push_back(e);
  }
  return world;
}

void integrate(ecs::World& world, float dt) {
  world.each<Position, const Velocity>([dt](Position& p, const Velocity& v) {
    p.x += v.x * dt;
    p.y += v.y * dt;
    p.z += v.z * dt;
  });
  clobber(world.pool<Position>()->data());
}

// One get<> per component per entity, through handles in creation order: the access pattern
// where the access check (engine/ecs/access.h) costs the most, one check per lookup.
void integrate_by_lookup(ecs::World& world, const std::vector<ecs::Entity>& handles, float dt) {
  for (const ecs::Entity e : handles) {
    Position& p = world.get<Position>(e);
    const Velocity& v = world.get<const Velocity>(e);
    p.x += v.x * dt;
    p.y += v.y * dt;
    p.z += v.z * dt;
  }
  clobber(&handles);
}

double position_sum(ecs::World& world) {
  double sum = 0;
  world.each<const Position>([&](const Position& p) { sum += double(p.x) + p.y + p.z; });
  return sum;
}

// A schedule of one system running `f` under the access the loops above need, so that every
// World call it makes is checked.
template <class F>
ecs::Schedule checked_schedule(F f) {
  ecs::Schedule schedule;
  schedule.set_threads(1);
  schedule.add({.name = "integrate",
                .access = ecs::Access::of<ecs::Reads<Velocity>, ecs::Writes<Position>>(),
                .run = std::move(f)});
  return schedule;
}

// The access check's cost, on one world (so memory placement cannot differ between the
// methods): the ECS loop and a loop of one get<> per component per entity, each run directly
// (unchecked) and by a scheduled system (every World call checked against its declared
// access), with plain arrays as the baseline, interleaved. The arrays get the world's four
// updates per repeat (one timed), so the two agree at the end.
nlohmann::json checked_access_costs(std::size_t n, int repeats, float dt) {
  std::vector<ecs::Entity> handles;
  ecs::World world = make_world(n, &handles);
  PlainArrays plain(n);
  ecs::Schedule each = checked_schedule([dt](ecs::World& w) { integrate(w, dt); });
  ecs::Schedule lookup =
      checked_schedule([&handles, dt](ecs::World& w) { integrate_by_lookup(w, handles, dt); });
  std::vector<double> t_plain, t_each, t_each_checked, t_lookup, t_lookup_checked;
  for (int r = 0; r <= repeats; ++r) {  // pass 0 warms up, untimed
    const double a = time_ns([&] { plain.integrate(dt); });
    for (int k = 0; k < 3; ++k) plain.integrate(dt);
    const double b = time_ns([&] { integrate(world, dt); });
    const double c = time_ns([&] { each.run_frame(world); });
    const double d = time_ns([&] { integrate_by_lookup(world, handles, dt); });
    const double e = time_ns([&] { lookup.run_frame(world); });
    if (r == 0) continue;
    t_plain.push_back(a), t_each.push_back(b), t_each_checked.push_back(c);
    t_lookup.push_back(d), t_lookup_checked.push_back(e);
  }
  const double per = 1.0 / double(n);
  const double plain_ns = mean_of_middles(t_plain) * per;
  const double each_ns = mean_of_middles(t_each) * per, each_checked_ns = mean_of_middles(t_each_checked) * per;
  const double lookup_ns = mean_of_middles(t_lookup) * per;
  const double lookup_checked_ns = mean_of_middles(t_lookup_checked) * per;
  return {
      {"ns_per_entity_checked", each_checked_ns},
      {"ecs_checked_ratio", each_checked_ns / plain_ns},
      {"checked_over_unchecked_each", each_checked_ns / each_ns},
      {"ns_per_lookup_unchecked", lookup_ns},
      {"ns_per_lookup_checked", lookup_checked_ns},
      {"lookup_checked_ratio", lookup_checked_ns / plain_ns},
      {"checked_over_unchecked_lookup", lookup_checked_ns / lookup_ns},
      {"checked_results_agree", position_sum(world) == plain.sum()},
  };
}

// n particles with the same starting values as the ECS world's entities and the plain arrays.
void fill_pool(ParticlePool& pool, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) {
    ParticleInit p;
    p.position = {init_value(i, 0), init_value(i, 1), init_value(i, 2)};
    p.velocity = {init_value(i, 3), init_value(i, 4), init_value(i, 5)};
    pool.spawn(p);
  }
}

}  // namespace

nlohmann::json bench_ecs(std::size_t n, int repeats, ProgressSink* progress_sink) {
  if (n == 0 || repeats < 1)
    throw std::invalid_argument("bench_ecs: need at least one item and one repeat");
  const float dt = 1.0f / 60.0f;

  // (1) ECS: n entities with Position and Velocity, owned by a group so each<> is a flat loop.
  ecs::World world = make_world(n);

  // (2) One ParticlePool of capacity n. A single pool keeps the loop the same shape as the
  // plain arrays, so the ratio isolates the container; per-emitter pools of 65536 would only
  // add a short outer loop over pools.
  ParticlePool pool(n);
  fill_pool(pool, n);

  // (3) Plain arrays.
  PlainArrays plain(n);

  auto run_ecs = [&] { integrate(world, dt); };
  auto run_pool = [&] {
    float* px = pool.px.data();
    float* py = pool.py.data();
    float* pz = pool.pz.data();
    const float* pvx = pool.vx.data();
    const float* pvy = pool.vy.data();
    const float* pvz = pool.vz.data();
    const std::size_t m = pool.size();
    // GCC cannot prove the pool's arrays distinct, and 3 stores against 6 streams need more
    // run-time alias checks than it will emit (10), so without this the loop stays scalar
    // (docs/benchmarks.md). See particle_pool.h.
#pragma GCC ivdep
    for (std::size_t i = 0; i < m; ++i) {
      px[i] += pvx[i] * dt;
      py[i] += pvy[i] * dt;
      pz[i] += pvz[i] * dt;
    }
    clobber(px);
  };
  // Here GCC sees six separate allocations and vectorises anyway; the pragma only keeps the
  // two loops textually identical.
  auto run_plain = [&] { plain.integrate(dt); };

  // One untimed pass each to fault in pages and warm caches, then ABC ABC ... so that all
  // three see the same machine noise.
  run_ecs(), run_pool(), run_plain();
  std::vector<double> t_ecs, t_pool, t_plain;
  ProgressTask progress(progress_sink, "bench ecs", size_t(repeats));
  for (int r = 0; r < repeats; ++r) {
    t_ecs.push_back(time_ns(run_ecs));
    t_pool.push_back(time_ns(run_pool));
    t_plain.push_back(time_ns(run_plain));
    progress.update(size_t(r) + 1);
  }
  progress.finish();

  // Every method did the same arithmetic from the same inputs, so the sums agree bitwise
  // (unless FMA contraction, off under ISO -std=c++20, fuses only some loops); reading the
  // results also keeps every store observable.
  const double sum_ecs = position_sum(world);
  const double sum_plain = plain.sum();
  double sum_pool = 0;
  for (std::size_t i = 0; i < n; ++i) sum_pool += double(pool.px[i]) + pool.py[i] + pool.pz[i];

  const double per = 1.0 / double(n);
  const double ecs_ns = mean_of_middles(t_ecs) * per;
  const double pool_ns = mean_of_middles(t_pool) * per;
  const double plain_ns = mean_of_middles(t_plain) * per;
  nlohmann::json result = {
      {"entities", n},
      {"repeats", repeats},
      {"ns_per_entity", ecs_ns},
      {"ns_per_particle_pool", pool_ns},
      {"ns_plain_arrays", plain_ns},
      {"ecs_ratio", ecs_ns / plain_ns},
      {"pool_ratio", pool_ns / plain_ns},
      {"pool_layout", "one ParticlePool of capacity n"},
      {"results_agree", sum_ecs == sum_pool && sum_pool == sum_plain},
  };
  result.update(checked_access_costs(n, repeats, dt));
  return result;
}

}  // namespace pyro
