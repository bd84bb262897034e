#pragma once
// Throughput of the update "position += velocity * dt" over n items, three ways in one run:
// ECS owning group, ParticlePool, plain std::vector<float> arrays. See bench_ecs.cpp.
#include <cstddef>
#include <nlohmann/json.hpp>

namespace pyro {

// Returns {"entities", "repeats", "ns_per_entity", "ns_per_particle_pool", "ns_plain_arrays",
// "ecs_ratio", "pool_ratio", ...}: median nanoseconds per item for each method and the two
// ratios against plain arrays.
nlohmann::json bench_ecs(std::size_t n, int repeats);

}  // namespace pyro
