// pyro view SCENE [--width W] [--height H] [--frames N] [--screenshot FILE] [--no-overlay]
//                 [--replace-at FRAME:FILE ...] [--press-at FRAME:KEY ...]
//                 [--set-at FRAME:/POINTER=VALUE ...] [--undo-at FRAME ...]
//                 [--screenshot-at FRAME:FILE ...] [--save-as FILE] [--inspect POINTER]
//                 [--expand PANEL ...] [--json]
//                 [render options]
//
// Parses the options and the scripted edits and presses, then runs the viewer
// (tools/viewer/viewer.h) and prints its summary.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/core/content_path.h"
#include "engine/core/user_error.h"
#include "engine/io/output_gate.h"
#include "engine/io/text_file.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/scene_runtime/scene_inputs.h"
#include "tools/viewer/viewer.h"
#include "tools/viewer/viewer_keys.h"
#include "tools/pyro/commands.h"
#include "tools/pyro/render_options.h"
#include "tools/pyro/stdout_text.h"

namespace pyro::cli {

namespace {

struct ViewArgs {
  std::string scene;
  int width = 0, height = 0;
  int frames = 0;  // 0: until the window is closed
  std::string screenshot;
  bool no_overlay = false;
  bool json = false;
  std::vector<std::string> replace_at;
  std::vector<std::string> press_at;
  std::vector<std::string> set_at;
  std::vector<uint64_t> undo_at;
  std::vector<std::string> screenshot_at;
  std::string save_as;
  std::string inspect;
  std::vector<std::string> expand;
  RuntimeOptions runtime;
};

uint64_t parse_frame_prefix(const std::string& spec, const char* option, const char* example,
                            std::string& rest);

std::vector<ViewerEdit> parse_edits(const std::vector<std::string>& specs) {
  std::vector<ViewerEdit> edits;
  for (const std::string& spec : specs) {
    std::string file;
    const uint64_t frame =
        parse_frame_prefix(spec, "--replace-at", "FILE, e.g. 10:broken_scene.json", file);
    edits.push_back({frame, read_text_file(file)});
  }
  return edits;
}

uint64_t parse_frame_prefix(const std::string& spec, const char* option, const char* example,
                            std::string& rest) {
  const size_t colon = spec.find(':');
  const std::string number = colon == std::string::npos ? "" : spec.substr(0, colon);
  if (number.empty() || number.find_first_not_of("0123456789") != std::string::npos ||
      number.size() > 9 || colon + 1 >= spec.size())
    throw UserError(spec, option, std::string("expected FRAME:") + example);
  rest = spec.substr(colon + 1);
  return std::stoull(number);
}

std::vector<ViewerPress> parse_presses(const std::vector<std::string>& specs) {
  std::vector<ViewerPress> presses;
  for (const std::string& spec : specs) {
    std::string name;
    const uint64_t frame = parse_frame_prefix(spec, "--press-at", "KEY, e.g. 10:SPACE", name);
    const std::optional<int> key = key_from_name(name);
    if (!key)
      throw UserError(spec, "--press-at",
                      "a key named 1-7, B, L, N, R, O, H, SPACE, TAB or ESC, found \"" + name + "\"");
    presses.push_back({frame, *key});
  }
  return presses;
}

// FRAME:/POINTER=VALUE. VALUE is JSON (3, [0, 1, 0], "text", true); a bare word that is not JSON
// is taken as a string, so that a choice needs no shell quoting (/render/particles=spherical).
std::vector<ViewerSet> parse_sets(const std::vector<std::string>& specs) {
  std::vector<ViewerSet> sets;
  for (const std::string& spec : specs) {
    std::string rest;
    const uint64_t frame = parse_frame_prefix(spec, "--set-at", "/POINTER=VALUE, e.g. 10:/clouds/0/density=0.6", rest);
    const size_t eq = rest.find('=');
    if (rest.empty() || rest[0] != '/' || eq == std::string::npos || eq + 1 >= rest.size())
      throw UserError(spec, "--set-at", "expected FRAME:/POINTER=VALUE, e.g. 10:/clouds/0/density=0.6");
    const std::string text = rest.substr(eq + 1);
    nlohmann::json value = nlohmann::json::parse(text, nullptr, false);
    if (value.is_discarded()) value = text;
    sets.push_back({frame, rest.substr(0, eq), std::move(value)});
  }
  return sets;
}

std::vector<ViewerScreenshot> parse_screenshots(const std::vector<std::string>& specs) {
  std::vector<ViewerScreenshot> shots;
  for (const std::string& spec : specs) {
    std::string file;
    const uint64_t frame = parse_frame_prefix(spec, "--screenshot-at", "FILE, e.g. 30:shot.png", file);
    shots.push_back({frame, file});
  }
  return shots;
}

// With --frames N the session ends after frame N - 1: a scripted action at a later frame would
// never happen, and what it was meant to change would be saved or shot unchanged.
void check_actions_within_frames(const ViewerOptions& o) {
  if (o.frames <= 0) return;
  const uint64_t end = uint64_t(o.frames);
  const auto refuse = [&](const char* option, uint64_t frame) {
    if (frame < end) return;
    throw UserError("", option, "actions at frames the session reaches, 0 to " + std::to_string(end - 1) +
                                    " with --frames " + std::to_string(end) + ", found one at frame " +
                                    std::to_string(frame));
  };
  for (const ViewerEdit& e : o.edits) refuse("--replace-at", e.frame);
  for (const ViewerPress& p : o.presses) refuse("--press-at", p.frame);
  for (const ViewerSet& s : o.sets) refuse("--set-at", s.frame);
  for (uint64_t u : o.undos) refuse("--undo-at", u);
  for (const ViewerScreenshot& s : o.screenshots) refuse("--screenshot-at", s.frame);
}

// Every file the session writes passes the gate (engine/io/output_gate.h).
void check_view_outputs(const ViewerOptions& o, const SceneDescription& scene) {
  OutputGate gate;
  gate.reads(scene_inputs(o.scene, scene));
  gate.writes_file(o.screenshot, "--screenshot");
  for (const ViewerScreenshot& s : o.screenshots) gate.writes_file(s.file, "--screenshot-at");
  gate.writes_file(o.save_as, "--save-as");
  gate.check();
}

void print_view_note(const std::string& note) { std::fprintf(stderr, "pyro view: %s\n", note.c_str()); }

void run_view(const ViewArgs& a) {
  // Everything the user can get wrong is checked before the window opens.
  ViewerOptions options;
  options.edits = parse_edits(a.replace_at);
  options.presses = parse_presses(a.press_at);
  options.sets = parse_sets(a.set_at);
  options.undos = a.undo_at;
  options.screenshots = parse_screenshots(a.screenshot_at);
  options.save_as = a.save_as;
  if (!a.inspect.empty() && a.inspect[0] != '/')
    throw UserError(a.inspect, "--inspect", "expected a JSON pointer, e.g. /clouds/0");
  options.inspect = a.inspect;
  options.expand = a.expand;
  options.scene = a.scene;
  options.width = a.width;
  options.height = a.height;
  options.frames = a.frames;
  options.screenshot = a.screenshot;
  options.overlay = !a.no_overlay;
  options.runtime = a.runtime;
  options.on_note = print_view_note;
  check_actions_within_frames(options);
  SceneDescription scene = load_scene(a.scene);
  check_view_outputs(options, scene);
  const nlohmann::json summary = run_viewer(options, std::move(scene));
  if (a.json) {
    write_stdout(summary.dump() + "\n");
  } else {
    std::printf("viewed %s: %llu frame(s) at %.1f fps (%dx%d)%s%s\n", a.scene.c_str(),
                summary["frames"].get<unsigned long long>(), summary["fps"].get<double>(),
                summary["width"].get<int>(), summary["height"].get<int>(),
                a.screenshot.empty() ? "" : ", screenshot ", a.screenshot.c_str());
  }
}

}  // namespace

void add_view_command(CLI::App& app) {
  auto args = std::make_shared<ViewArgs>();
  CLI::App* cmd = app.add_subcommand(
      "view", "Interactive viewer: a window with orbit/fly camera, hot reload and an overlay "
              "(keys: " + key_help_title() + ")");
  cmd->add_option("scene", args->scene, "Scene file (JSON), e.g. content/scenes/explosion.json")->required();
  cmd->add_option("--width", args->width, "View width in pixels (default: the scene's)")
      ->check(CLI::Range(1, 8192));
  cmd->add_option("--height", args->height, "View height in pixels (default: the scene's)")
      ->check(CLI::Range(1, 8192));
  cmd->add_option("--frames", args->frames, "Render this many frames, then exit (0: until closed)")
      ->check(CLI::Range(0, 100000000));
  cmd->add_option("--screenshot", args->screenshot,
                  "Save the window's image as PNG after the last frame (or when closed)");
  cmd->add_flag("--no-overlay", args->no_overlay, "Start with the panels hidden: status, inspector, profiler, stereo (O shows them)");
  cmd->add_option("--replace-at", args->replace_at,
                  "FRAME:FILE: at that frame, write FILE's content over the scene file (as an "
                  "editor would; the hot reload picks it up). Repeatable; for tests and demos");
  cmd->add_option("--press-at", args->press_at,
                  "FRAME:KEY: press KEY (1-7, B, L, N, R, O, H, SPACE, TAB, ESC) at that frame. "
                  "Repeatable; for tests and demos");
  cmd->add_option("--inspect", args->inspect,
                  "POINTER: open the inspector at this entity or key, e.g. /clouds/0");
  cmd->add_option("--expand", args->expand,
                  "PANEL: start with this panel expanded (status, inspector, profiler, stereo; the "
                  "status is, and the inspector with --inspect). Repeatable")
      ->check(CLI::IsMember({"status", "inspector", "profiler", "stereo"}));
  cmd->add_option("--set-at", args->set_at,
                  "FRAME:/POINTER=VALUE: at that frame, set the scene's value at the JSON pointer, as "
                  "the inspector does (VALUE is JSON; a bare word is a string). Repeatable; a value "
                  "the loader refuses ends the session with its message and nothing saved");
  cmd->add_option("--undo-at", args->undo_at, "FRAME: undo the last edit at that frame. Repeatable")
      ->check(CLI::Range(0, 100000000));
  cmd->add_option("--screenshot-at", args->screenshot_at,
                  "FRAME:FILE: save the window's image as PNG at that frame. Repeatable");
  cmd->add_option("--save-as", args->save_as,
                  "Save the edited scene to FILE after the last frame (atomically; keys keep their "
                  "order and untouched values their text)");
  cmd->add_flag("--json", args->json, "Print a JSON summary as the last line");
  add_render_options(cmd, args->runtime);
  cmd->callback([args] { run_view(*args); });
}

}  // namespace pyro::cli
