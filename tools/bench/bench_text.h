#pragma once
// The benchmarks' results (JSON) as the text the command line prints for people.
#include <nlohmann/json.hpp>
#include <string>

namespace pyro {

// One line per field: its name and its JSON value.
std::string bench_fields_text(const nlohmann::json& result);

// pyro bench scale (bench_scale.h): one line per count, then the slopes.
std::string scale_bench_text(const nlohmann::json& result);

// pyro bench import-scale (import_scale.h): size, times, error and peak memory.
std::string import_scale_text(const nlohmann::json& result);

// pyro profile (profile_report.h): the tables of systems, GPU passes and particles.
std::string profile_tables_text(const nlohmann::json& report);

}  // namespace pyro
