#pragma once
// The `pyro` subcommands. Each registers itself on the CLI11 app and runs when chosen.
#include <CLI/CLI.hpp>

namespace pyro::cli {

void add_render_command(CLI::App& app);
void add_analyze_commands(CLI::App& app);
void add_bench_commands(CLI::App& app);
void add_import_command(CLI::App& app);
void add_export_vdb_command(CLI::App& app);  // command_export_vdb.cpp
// `pyro bake-flipbook` and `pyro analyze flipbook-pattern` (command_flipbook.cpp).
void add_flipbook_commands(CLI::App& app, CLI::App& analyze);
// `pyro analyze six-way`, registered by add_flipbook_commands (command_six_way.cpp).
void add_six_way_analysis(CLI::App& analyze);
void add_profile_command(CLI::App& app);  // command_profile.cpp
void add_quality_command(CLI::App& app);  // command_quality.cpp
void add_view_command(CLI::App& app);  // command_view.cpp: the interactive viewer
void add_chart_command(CLI::App& app);  // command_chart.cpp
void add_schema_command(CLI::App& app);  // command_schema.cpp: the scene files' JSON Schema
void add_new_command(CLI::App& app);     // command_new.cpp: a starting scene from a template
// `pyro farm submit|collect|resubmit` (command_farm.cpp): a sequence on a Slurm cluster.
void add_farm_command(CLI::App& app);
// Registered under `pyro analyze` by add_analyze_commands.
void add_billboard_mode_analysis(CLI::App& analyze);
// `pyro bench vdb`, `pyro bench schedule` (command_bench_schedule.cpp) and `pyro bench import-scale`, registered by
// add_bench_commands.
void add_bench_vdb_command(CLI::App& bench);
void add_bench_schedule_command(CLI::App& bench);
void add_bench_import_scale_command(CLI::App& bench);  // command_bench_import_scale.cpp
void add_bench_vdb_sequence_command(CLI::App& bench);  // command_bench_vdb_sequence.cpp
void add_bench_relight_command(CLI::App& bench);       // command_bench_relight.cpp
void add_bench_multiple_scattering_command(CLI::App& bench);  // command_bench_multiple_scattering.cpp
void add_bench_cycles_command(CLI::App& bench);       // command_bench_cycles.cpp
void add_bench_cycles_fire_command(CLI::App& bench);  // command_bench_cycles_fire.cpp
void add_bench_cycles_scene_command(CLI::App& bench);  // command_bench_cycles_scene.cpp
void add_bench_explosion_shadows_command(CLI::App& bench);  // command_bench_explosion_shadows.cpp
void add_bench_export_vdb_command(CLI::App& bench);  // command_bench_export_vdb.cpp

// Subcommands of `pyro analyze`, registered by add_analyze_commands.
void add_analyze_projection_error_command(CLI::App& analyze);  // command_analyze_alignment.cpp
void add_analyze_stereo_command(CLI::App& analyze);            // command_analyze_stereo.cpp
void add_analyze_media_commands(CLI::App& analyze);  // blackbody, phase: command_analyze_media.cpp

}  // namespace pyro::cli
