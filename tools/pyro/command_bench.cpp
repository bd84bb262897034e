// pyro bench ecs | sort | scale | import-cases | render | johnson | layers | table1 | soak | vdb | relight | multiple-scattering | cycles | cycles-fire | cycles-scene | schedule ... [--json]
//
// Each subcommand parses its options, runs the benchmark (tools/bench; bench ecs:
// tools/bench/bench_ecs.h) and prints its result.
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "tools/bench/bench_ecs.h"
#include "tools/bench/bench_johnson.h"
#include "tools/bench/bench_layers.h"
#include "tools/bench/import_cases.h"
#include "tools/bench/bench_render.h"
#include "tools/bench/bench_scale.h"
#include "tools/bench/bench_soak.h"
#include "tools/bench/bench_sort.h"
#include "tools/bench/bench_text.h"
#include "tools/pyro/commands.h"
#include "tools/pyro/progress.h"
#include "tools/pyro/render_options.h"
#include "tools/pyro/stdout_text.h"

namespace pyro::cli {

namespace {

void print(const nlohmann::json& result, bool json) {
  write_result(result, bench_fields_text(result), json);
}

void add_bench_ecs(CLI::App* bench) {
  struct EcsArgs { size_t entities = 1000000; int repeats = 15; bool json = false; };
  auto ecs = std::make_shared<EcsArgs>();
  CLI::App* ecs_cmd = bench->add_subcommand(
      "ecs", "position += velocity * dt: ECS query and particle pools against plain arrays");
  ecs_cmd->add_option("--entities", ecs->entities, "Items updated")->check(CLI::Range(1, 100000000));
  ecs_cmd->add_option("--repeats", ecs->repeats, "Interleaved repeats (medians reported)")
      ->check(CLI::Range(1, 1000));
  ecs_cmd->add_flag("--json", ecs->json, "Print one JSON object");
  ecs_cmd->callback([ecs] { print(bench_ecs(ecs->entities, ecs->repeats, terminal_progress()), ecs->json); });
}

void add_bench_sort(CLI::App* bench) {
  struct SortArgs { size_t count = 1500000; int repeats = 9; bool json = false; };
  auto sort = std::make_shared<SortArgs>();
  CLI::App* cmd = bench->add_subcommand(
      "sort", "The draw order's radix sort against std::sort and tbb::parallel_sort of the same keys");
  cmd->add_option("--count", sort->count, "Keys sorted")->check(CLI::Range(1, 100000000));
  cmd->add_option("--repeats", sort->repeats, "Timings per method (medians reported)")
      ->check(CLI::Range(1, 1000));
  cmd->add_flag("--json", sort->json, "Print one JSON object");
  cmd->callback([sort] { print(bench_sort(sort->count, sort->repeats), sort->json); });
}

// One line per count, then the slopes.
void add_bench_scale(CLI::App* bench) {
  struct ScaleArgs { ScaleBenchOptions options; bool json = false; };
  auto scale = std::make_shared<ScaleArgs>();
  CLI::App* cmd = bench->add_subcommand(
      "scale", "CPU cost per frame as the clouds' particle count grows (radius scaled as count^(-1/3)), "
               "against std::sort and memcpy of the same data");
  cmd->add_option("scene", scale->options.scene, "Scene file with clouds (JSON)")->required();
  cmd->add_option("--counts", scale->options.counts, "Particle counts (default 1e5 2e5 5e5 1e6 1.5e6 2e6)")
      ->check(CLI::Range(uint64_t(1), uint64_t(10000000)))
      ->expected(1, 32);
  cmd->add_option("--frames", scale->options.frames, "Timed frames per count (after one warm-up)")
      ->check(CLI::Range(1, 1000));
  cmd->add_option("--width", scale->options.width, "Width (default: the scene's)")->check(CLI::Range(1, 8192));
  cmd->add_option("--height", scale->options.height, "Height (default: the scene's)")->check(CLI::Range(1, 8192));
  cmd->add_option("--threads", scale->options.threads, "Schedule threads (0: one per core)")
      ->check(CLI::Range(0, 256));
  cmd->add_flag("--no-cull", [scale](std::int64_t) { scale->options.cull = false; },
                "Sort and draw every particle, also those the view cannot show (to compare)");
  add_enum_option<SortDevice>(cmd, "--sort-device", [scale](SortDevice d) { scale->options.sort_device = d; },
                              "Where the draw order is made (default auto: the faster, measured)");
  cmd->add_flag("--json", scale->json, "Print one JSON object");
  cmd->callback([scale] {
    scale->options.progress = terminal_progress();
    const nlohmann::json r = bench_scale(scale->options);
    write_result(r, scale_bench_text(r), scale->json);
  });
}

void add_bench_import_cases(CLI::App* bench) {
  struct CasesArgs { ImportCasesOptions options; bool json = false; };
  auto cases = std::make_shared<CasesArgs>();
  CLI::App* cmd = bench->add_subcommand(
      "import-cases", "The import's hard cases (box, torus shell, sphere, noise cloud, sheet) at each "
                      "error target, from every side");
  cmd->add_option("--errors", cases->options.error_targets, "Error targets (default 0.03 0.01)")
      ->check(CLI::Range(1e-6, 1.0))
      ->expected(1, 16);
  cmd->add_option("--width", cases->options.width, "Width of each view (default 128)")->check(CLI::Range(16, 4096));
  cmd->add_option("--height", cases->options.height, "Height of each view (default 128)")->check(CLI::Range(16, 4096));
  cmd->add_flag("--json", cases->json, "Print one JSON object");
  cmd->callback([cases] {
    cases->options.progress = terminal_progress();
    print(bench_import_cases(cases->options), cases->json);
  });
}

void add_bench_render(CLI::App* bench) {
  struct RenderArgs { RenderBenchOptions options; bool json = false; };
  auto render = std::make_shared<RenderArgs>();
  CLI::App* render_cmd = bench->add_subcommand(
      "render", "Frame time, fragment rate and efficiency against a trivial blending shader");
  render_cmd->add_option("scene", render->options.scene, "Scene file (JSON)")->required();
  render_cmd->add_option("--width", render->options.width, "Width (default: the scene's)")->check(CLI::Range(1, 8192));
  render_cmd->add_option("--height", render->options.height, "Height (default: the scene's)")->check(CLI::Range(1, 8192));
  render_cmd->add_option("--frames", render->options.frames, "Timed frames")->check(CLI::Range(1, 100000));
  render_cmd->add_option("--repeats", render->options.pass_repeats, "Timed particle passes per shader")
      ->check(CLI::Range(1, 10000));
  render_cmd->add_flag("--json", render->json, "Print one JSON object");
  render_cmd->callback([render] {
    render->options.progress = terminal_progress();
    print(bench_render(render->options), render->json);
  });
}

void add_bench_johnson(CLI::App* bench) {
  struct JohnsonArgs { JohnsonBenchOptions options; bool json = false; };
  auto johnson = std::make_shared<JohnsonArgs>();
  CLI::App* johnson_cmd = bench->add_subcommand(
      "johnson", "The paper's performance test: anaglyph stereo at 1024x768 moving through the volume");
  johnson_cmd->add_option("--frames", johnson->options.frames, "Frames along the path per scene")
      ->check(CLI::Range(2, 100000));
  johnson_cmd->add_option("--width", johnson->options.width, "Width per eye (the paper: 1024)")
      ->check(CLI::Range(16, 8192));
  johnson_cmd->add_option("--height", johnson->options.height, "Height (the paper: 768)")
      ->check(CLI::Range(16, 8192));
  johnson_cmd->add_option("--layer-scale", johnson->options.layer_scale,
                          "Particle layer resolution: 1, 0.5, 0.25, 0.125")
      ->check(CLI::IsMember({1.0f, 0.5f, 0.25f, 0.125f}));
  johnson_cmd->add_option("--frame-scale", johnson->options.frame_scale,
                          "Render the views at this fraction of the output and upscale: 1, 0.5, 0.25")
      ->check(CLI::IsMember({1.0f, 0.5f, 0.25f}));
  johnson_cmd->add_option("--error-samples", johnson->options.error_samples,
                          "Frames where the layer's RMSE against full resolution is measured")
      ->check(CLI::Range(0, 1000));
  johnson_cmd->add_flag("--sync-timing", johnson->options.sync_timing,
                        "Finish GPU work after each system so per-system times include it");
  johnson_cmd->add_flag("--json", johnson->json, "Print one JSON object");
  johnson_cmd->callback([johnson] {
    johnson->options.progress = terminal_progress();
    print(bench_johnson(johnson->options), johnson->json);
  });
}

void add_bench_layers(CLI::App* bench) {
  struct LayersArgs {
    LayersBenchOptions options;
    bool json = false;
  };
  auto layers = std::make_shared<LayersArgs>();
  CLI::App* layers_cmd = bench->add_subcommand(
      "layers", "Explosion media layers at 1, 1/2, 1/4, 1/8: fps and RMSE against full resolution");
  layers_cmd->add_option("scene", layers->options.scene, "Scene file (JSON)")->required();
  layers_cmd->add_option("--width", layers->options.width, "Width")->check(CLI::Range(16, 8192));
  layers_cmd->add_option("--height", layers->options.height, "Height")->check(CLI::Range(16, 8192));
  layers_cmd->add_option("--frames", layers->options.frames, "Timed frames per scale")->check(CLI::Range(1, 100000));
  layers_cmd->add_flag("--sync-timing", layers->options.sync_timing,
                       "Finish GPU work after each system so per-system times include it");
  layers_cmd->add_option("--scales", layers->options.scales,
                         "Layer scales to run (default 1 0.5 0.25 0.125; speed-ups are against the first)")
      ->check(CLI::Range(0.01f, 1.0f))
      ->expected(1, 8);
  LayersBenchOptions& lo = layers->options;
  add_enum_option<LayerUpsampling>(
      layers_cmd, "--upsampling", [&lo](LayerUpsampling v) { lo.upsampling = v; },
      "How reduced layers are upsampled (default the first)");
  add_enum_option<ComposeMode>(
      layers_cmd, "--compose", [&lo](ComposeMode v) { lo.compose = v; },
      "Final pass, tiled by the work each tile needs or the full variant per pixel (the same "
      "image; default the first)");
  add_enum_option<BillboardGeometry>(
      layers_cmd, "--billboards", [&lo](BillboardGeometry v) { lo.billboards = v; },
      "Billboard primitive, point sprites where they fit or quads (the same image; default the first)");
  layers_cmd->add_flag("--json", layers->json, "Print one JSON object");
  layers_cmd->callback([layers] {
    layers->options.progress = terminal_progress();
    print(bench_layers(layers->options), layers->json);
  });
}

void add_bench_table1(CLI::App* bench) {
  struct Table1Args { Table1BenchOptions options; bool json = false; };
  auto table1 = std::make_shared<Table1Args>();
  CLI::App* table1_cmd = bench->add_subcommand(
      "table1", "Umenhoffer et al. 2006 Table 1: 0-1578 particles, planar and spherical, half-resolution layers");
  table1_cmd->add_option("--scene", table1->options.scene, "Explosion scene (JSON)");
  table1_cmd->add_option("--frames", table1->options.frames, "Timed frames per row")->check(CLI::Range(1, 100000));
  table1_cmd->add_flag("--json", table1->json, "Print one JSON object");
  table1_cmd->callback([table1] {
    table1->options.progress = terminal_progress();
    print(bench_table1(table1->options), table1->json);
  });
}

void add_bench_soak(CLI::App* bench) {
  struct SoakArgs { SoakBenchOptions options; bool json = false; };
  auto soak = std::make_shared<SoakArgs>();
  CLI::App* soak_cmd = bench->add_subcommand(
      "soak", "Long run: N frames simulated; NaN in the particles, resident memory and time per frame");
  soak_cmd->add_option("scene", soak->options.scene, "Scene file (JSON)")->required();
  soak_cmd->add_option("--frames", soak->options.frames, "Frames simulated")->check(CLI::Range(10L, 100000000L));
  soak_cmd->add_option("--render-every", soak->options.render_every,
                       "Render every k-th frame (0: simulate only)")->check(CLI::Range(0, 1000000));
  soak_cmd->add_option("--rearm-every", soak->options.rearm_every,
                       "Fire the emitters' bursts again every this many seconds of scene time (0: never)")
      ->check(CLI::Range(0.0, 1e9));
  soak_cmd->add_option("--width", soak->options.width, "Width when rendering")->check(CLI::Range(16, 8192));
  soak_cmd->add_option("--height", soak->options.height, "Height when rendering")->check(CLI::Range(16, 8192));
  soak_cmd->add_flag("--json", soak->json, "Print one JSON object");
  soak_cmd->callback([soak] {
    soak->options.progress = terminal_progress();
    print(bench_soak(soak->options), soak->json);
  });
}

}  // namespace

void add_bench_commands(CLI::App& app) {
  CLI::App* bench = app.add_subcommand("bench", "Benchmarks, printed as ratios to a baseline run alongside");
  bench->require_subcommand(1);
  add_bench_vdb_command(*bench);
  add_bench_schedule_command(*bench);
  add_bench_import_scale_command(*bench);
  add_bench_vdb_sequence_command(*bench);
  add_bench_relight_command(*bench);
  add_bench_multiple_scattering_command(*bench);
  add_bench_cycles_command(*bench);
  add_bench_cycles_fire_command(*bench);
  add_bench_cycles_scene_command(*bench);
  add_bench_explosion_shadows_command(*bench);
  add_bench_export_vdb_command(*bench);

  for (const auto add : {add_bench_ecs, add_bench_sort, add_bench_scale, add_bench_import_cases, add_bench_render, add_bench_johnson, add_bench_layers,
                         add_bench_table1, add_bench_soak})
    add(bench);
}

}  // namespace pyro::cli
