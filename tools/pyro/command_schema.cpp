// pyro schema [--out FILE]
//
// Prints the JSON Schema (draft 2020-12) of scene files, derived from the scene's key tables
// (systems/runtime/scene/scene_keys.h): what editors use for completion and checking when a scene names
// it with "$schema" (content/scene.schema.json is this output, checked by a test).
#include <memory>
#include <string>

#include "engine/io/output_gate.h"
#include "engine/io/text_file.h"
#include "systems/runtime/scene/scene_keys.h"
#include "tools/pyro/commands.h"
#include "tools/pyro/stdout_text.h"

namespace pyro::cli {

void add_schema_command(CLI::App& app) {
  auto out = std::make_shared<std::string>();
  CLI::App* cmd = app.add_subcommand(
      "schema", "Print the JSON Schema of scene files (for editors and validators)");
  cmd->add_option("--out", *out, "Write it to this file instead of standard output (-: standard output)");
  cmd->callback([out] {
    OutputGate().writes({*out, "--out", OutputShape::file, {}, false, true}).check();
    const std::string text = scene_schema().dump(2) + "\n";
    if (out->empty() || *out == "-")
      write_stdout(text);
    else
      write_text_file(*out, text);
  });
}

}  // namespace pyro::cli
