// pyro new FILE --template NAME [--force] | pyro new --list
//
// Writes a starting scene (content/templates/NAME.json, tools/authoring/scene_templates.h) to FILE,
// atomically, with "$schema" and its asset paths rewritten to resolve from FILE's folder, so
// that it renders as it is and editors find the schema.
#include <filesystem>
#include <memory>
#include <string>

#include "engine/core/user_error.h"
#include "engine/io/durable_file.h"
#include "engine/io/output_gate.h"
#include "engine/io/parameter_text.h"
#include "tools/pyro/commands.h"
#include "tools/authoring/scene_templates.h"
#include "tools/pyro/stdout_text.h"

namespace pyro::cli {
namespace {

namespace fs = std::filesystem;

struct NewArgs {
  std::string file, template_name;
  bool force = false, list = false;
};

std::string template_list() {
  std::string text;
  for (const SceneTemplate& t : scene_templates()) {
    text += t.name + std::string(t.name.size() < 10 ? 10 - t.name.size() : 1, ' ');
    text += (t.description.rfind(t.name + ": ", 0) == 0 ? t.description.substr(t.name.size() + 2) : t.description);
    text += "\n";
  }
  return text;
}

// FILE's folder must exist, and FILE must not (unless --force, and then not as a folder).
void check_new_scene_destination(const std::string& file, bool force) {
  const fs::path folder = fs::absolute(file).parent_path();
  std::error_code ec;
  if (!fs::is_directory(folder, ec))
    throw UserError(file, "", "expected a file in an existing folder; there is no folder " + in_quotes(folder.string()));
  const fs::file_status status = fs::symlink_status(file, ec);
  if (status.type() == fs::file_type::directory)
    throw UserError(file, "", "expected the path of a scene file to write, found a folder");
  if (status.type() != fs::file_type::not_found && !force)
    throw UserError(file, "", "a file exists there already; pass --force to replace it");
}

void run_new(const NewArgs& args) {
  if (args.list) {
    write_stdout(template_list());
    return;
  }
  if (args.file.empty()) throw UserError("", "FILE", "expected the path of the scene file to write");
  if (args.template_name.empty())
    throw UserError("", "--template", "expected a template name (pyro new --list shows them)");
  const SceneTemplate t = find_scene_template(args.template_name);
  check_new_scene_destination(args.file, args.force);
  OutputGate().reads(t.path, "the template").writes_file(args.file, "FILE").check();
  write_file_durably(args.file, scene_template_text(t, args.file));
  write_stdout("wrote " + args.file + " from the " + t.name + " template (pyro render " + args.file +
               " --out DIR renders it)\n");
}

}  // namespace

void add_new_command(CLI::App& app) {
  auto args = std::make_shared<NewArgs>();
  CLI::App* cmd = app.add_subcommand(
      "new", "Write a starting scene from a template: clouds, fog, explosion, campfire, vdb or smoke");
  cmd->add_option("file", args->file, "The scene file to write (its folder must exist)");
  cmd->add_option("--template", args->template_name, "The template's name (--list shows them)");
  cmd->add_flag("--force", args->force, "Replace FILE when it exists");
  cmd->add_flag("--list", args->list, "List the templates, one line each, and exit");
  cmd->callback([args] { run_new(*args); });
}

}  // namespace pyro::cli
