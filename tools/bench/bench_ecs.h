#pragma once
// Throughput of the update "position += velocity * dt" over n items, three ways in one run:
// ECS owning group, ParticlePool, plain std::vector<float> arrays. See bench_ecs.cpp. Also the
// cost of the schedule's access check: the ECS loop, and a loop of one get<> per component per
// entity, each run by a scheduled system (checked) and directly (unchecked).
#include <cstddef>
#include <nlohmann/json.hpp>

#include "engine/core/progress_sink.h"

namespace pyro {

// Returns {"entities", "repeats", "ns_per_entity", "ns_per_particle_pool", "ns_plain_arrays",
// "ecs_ratio", "pool_ratio", "ecs_checked_ratio", "checked_over_unchecked_each",
// "checked_over_unchecked_lookup", ...}: median nanoseconds per item for each method and the
// ratios against plain arrays, and checked against unchecked. The repeats report to `progress_sink`
// (null: nowhere).
nlohmann::json bench_ecs(std::size_t n, int repeats, ProgressSink* progress_sink);

}  // namespace pyro
