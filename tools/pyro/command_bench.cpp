// pyro bench ecs --entities N [--repeats R] --json
// pyro bench render SCENE [--width W] [--height H] [--frames N] --json
#include <cstdio>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "tools/pyro/bench_ecs.h"
#include "tools/pyro/bench_render.h"
#include "tools/pyro/commands.h"

namespace pyro::cli {

namespace {

void print(const nlohmann::json& result, bool json) {
  if (json) {
    std::printf("%s\n", result.dump().c_str());
  } else {
    for (const auto& [key, value] : result.items()) std::printf("  %-30s %s\n", key.c_str(), value.dump().c_str());
  }
}

}  // namespace

void add_bench_commands(CLI::App& app) {
  CLI::App* bench = app.add_subcommand("bench", "Benchmarks, printed as ratios to a baseline run alongside");
  bench->require_subcommand(1);
  add_bench_vdb_command(*bench);

  struct EcsArgs { size_t entities = 1000000; int repeats = 15; bool json = false; };
  auto ecs = std::make_shared<EcsArgs>();
  CLI::App* ecs_cmd = bench->add_subcommand(
      "ecs", "position += velocity * dt: ECS query and particle pools against plain arrays");
  ecs_cmd->add_option("--entities", ecs->entities, "Items updated")->check(CLI::Range(1, 100000000));
  ecs_cmd->add_option("--repeats", ecs->repeats, "Interleaved repeats (medians reported)")
      ->check(CLI::Range(1, 1000));
  ecs_cmd->add_flag("--json", ecs->json, "Print one JSON object");
  ecs_cmd->callback([ecs] { print(bench_ecs(ecs->entities, ecs->repeats), ecs->json); });

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
  render_cmd->callback([render] { print(bench_render(render->options), render->json); });
}

}  // namespace pyro::cli
