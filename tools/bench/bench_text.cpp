#include "tools/bench/bench_text.h"

#include <cmath>
#include <cstdint>

#include "engine/core/format_text.h"

namespace pyro {

std::string bench_fields_text(const nlohmann::json& result) {
  std::string text;
  for (const auto& [key, value] : result.items())
    text += format_text("  %-30s %s\n", key.c_str(), value.dump().c_str());
  return text;
}

std::string scale_bench_text(const nlohmann::json& r) {
  std::string text;
  text += format_text("%s at %dx%d, %d frames per count\n", r["scene"].get<std::string>().c_str(),
                      r["width"].get<int>(), r["height"].get<int>(), r["frames"].get<int>());
  text += format_text("%12s %12s %12s %14s %18s %8s\n", "particles", "ms/frame", "cpu ms",
                      "sort/std::sort", "instances/memcpy", "order");
  const auto number = [](const nlohmann::json& v) { return v.is_null() ? NAN : v.get<double>(); };
  for (const nlohmann::json& c : r["counts"])
    text += format_text("%12llu %12.1f %12.2f %14.3f %18.2f %8s\n",
                        c["particles"].get<unsigned long long>(), c["ms_per_frame"].get<double>(),
                        c["cpu_ms_per_frame"].get<double>(), number(c["sort_over_std_sort"]),
                        c["instances_over_memcpy"].get<double>(),
                        c["ordered_on"].get<std::string>().c_str());
  for (const char* slope : {"cpu_slope", "frame_slope"})
    text += format_text(
        "%s (log-log, 1e5 to 2e6): %s\n", slope,
        r[slope].is_null() ? "none (fewer than two counts there)" : r[slope].dump().c_str());
  return text;
}

std::string import_scale_text(const nlohmann::json& j) {
  std::string text;
  const double gib = double(uint64_t{1} << 30);
  text += format_text(
      "%llu active voxels (%llu bricks of 8^3, box %llu voxels), file %.2f GiB%s\n",
      j["active_voxels"].get<unsigned long long>(), j["bricks"].get<unsigned long long>(),
      j["box_voxels"].get<unsigned long long>(), j["file_bytes"].get<double>() / gib,
      j["generated"].get<bool>() ? " (written for this run)" : "");
  text += format_text(
      "read %.2f s, import %.2f s (light %.2f s, pyramid and octree %.2f s): %.2f M active "
      "voxels/s, "
      "%llu particles\n",
      j["read_seconds"].get<double>(), j["import_seconds"].get<double>(),
      j["light_seconds"].get<double>(), j["fit_seconds"].get<double>(),
      j["voxels_per_second"].get<double>() / 1e6, j["particles"].get<unsigned long long>());
  if (j["measured"].get<bool>())
    text += format_text(
        "import error: RMSE %.4f against the path-traced truth of the sparse grid (%dx%d, %d paths "
        "per "
        "pixel, its own Monte Carlo error %.4f, %.1f s)\n",
        j["rmse_vs_reference"].get<double>(), j["error_size"].get<int>(),
        j["error_size"].get<int>(), j["error_samples"].get<int>(),
        j["reference_monte_carlo_error"].get<double>(), j["reference_seconds"].get<double>());
  text += format_text("peak resident memory: engine %.2f GiB, reading child %.2f GiB\n",
                      j["parent_peak_rss_bytes"].get<double>() / gib,
                      j["child_peak_rss_bytes"].get<double>() / gib);
  return text;
}

std::string profile_tables_text(const nlohmann::json& r) {
  std::string text;
  text += format_text("%-20s %-10s %9s %9s %9s %9s %9s\n", "system", "phase", "mean ms", "p95 ms",
                      "max ms", "GPU mean", "GPU p95");
  for (const auto& row : r["systems"]) {
    text += format_text("%-20s %-10s %9.3f %9.3f %9.3f", row["name"].get<std::string>().c_str(),
                        row["phase"].get<std::string>().c_str(), row["mean_ms"].get<double>(),
                        row["p95_ms"].get<double>(), row["max_ms"].get<double>());
    if (row.contains("gpu_mean_ms"))
      text += format_text(" %9.3f %9.3f\n", row["gpu_mean_ms"].get<double>(),
                          row["gpu_p95_ms"].get<double>());
    else
      text += format_text(" %9s %9s\n", "-", "-");
  }
  text += format_text("%-32s %9s %9s %14s\n", "GPU pass", "mean ms", "p95 ms", "fragments");
  for (const auto& row : r["gpu_passes"]) {
    text += format_text("%-32s %9.3f %9.3f", row["name"].get<std::string>().c_str(),
                        row["mean_ms"].get<double>(), row["p95_ms"].get<double>());
    if (row.contains("fragments_mean"))
      text += format_text(" %14.0f\n", row["fragments_mean"].get<double>());
    else
      text += format_text(" %14s\n", "-");
  }
  const nlohmann::json& p = r["particles"];
  text += format_text(
      "particles: %llu live of %llu slots; %zu bytes per slot, %.1f bytes of pool per live "
      "particle\n",
      p["live"].get<unsigned long long>(), p["capacity"].get<unsigned long long>(),
      r["memory"]["bytes_per_particle_slot"].get<size_t>(),
      r["memory"]["pool_bytes_per_live_particle"].get<double>());
  for (const auto& s : p["sources"])
    text +=
        format_text("  %-18s %llu live of %llu\n", s["name"].get<std::string>().c_str(),
                    s["live"].get<unsigned long long>(), s["capacity"].get<unsigned long long>());
  return text;
}

}  // namespace pyro
