// pyro view SCENE [--width W] [--height H] [--frames N] [--screenshot FILE] [--no-overlay]
//                 [--replace-at FRAME:FILE ...] [--json] [render options]
//
// The interactive viewer: a GLFW window (engine/gpu/window_context.h) whose context the scene
// runtime renders with; each frame the runtime's output target is blitted to the window and the
// overlay drawn over it. The logic lives in window-free files with their own tests: the keys
// (viewer_keys.h), what they change (viewer_settings.h), the camera (engine/math/view_controller.h),
// hot reload (scene_reloader.h) and the overlay's text (viewer_overlay.h). This file is the glue.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <nlohmann/json.hpp>

#include "components/camera.h"
#include "components/camera_orbit.h"
#include "components/draw_list.h"
#include "engine/core/content_path.h"
#include "engine/core/user_error.h"
#include "engine/gpu/gpu_error.h"
#include "engine/gpu/window_context.h"
#include "engine/io/png_file.h"
#include "systems/scene/scene_loader.h"
#include "engine/math/view_controller.h"
#include "systems/scene_runtime/scene_runtime.h"
#include "tools/pyro/commands.h"
#include "tools/pyro/render_options.h"
#include "tools/pyro/scene_reloader.h"
#include "tools/pyro/viewer_keys.h"
#include "tools/pyro/viewer_overlay.h"
#include "tools/pyro/viewer_settings.h"
#include "tools/pyro/viewer_text_renderer.h"

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
  RuntimeOptions runtime;
};

// --replace-at FRAME:FILE: at that frame the viewer writes FILE's content over the scene file,
// in place, as an editor saving would; the hot reload then finds the edit like any other.
struct ScriptedEdit {
  uint64_t frame = 0;
  std::string content;
};

uint64_t parse_frame_prefix(const std::string& spec, const char* option, const char* example,
                            std::string& rest);

std::vector<ScriptedEdit> parse_edits(const std::vector<std::string>& specs) {
  std::vector<ScriptedEdit> edits;
  for (const std::string& spec : specs) {
    std::string file;
    const uint64_t frame =
        parse_frame_prefix(spec, "--replace-at", "FILE, e.g. 10:broken_scene.json", file);
    edits.push_back({frame, read_text_file(file)});
  }
  return edits;
}

// --press-at FRAME:KEY: the key is pressed at that frame, through the same path as a real press.
struct ScriptedPress {
  uint64_t frame = 0;
  int key = 0;
};

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

std::vector<ScriptedPress> parse_presses(const std::vector<std::string>& specs) {
  std::vector<ScriptedPress> presses;
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

int output_width(int view_width, StereoMode mode) {
  return two_views_wide(mode) ? 2 * view_width : view_width;
}

std::string error_text(const std::exception& e) { return e.what(); }

class Viewer {
 public:
  Viewer(const ViewArgs& args, SceneDescription scene)
      : args_(args),
        scene_(std::move(scene)),
        window_(output_width(args.width > 0 ? args.width : scene_.width,
                             args.runtime.stereo_mode),
                args.height > 0 ? args.height : scene_.height,
                "pyro view - " + args.scene + " - " + key_help_title()),
        text_(window_.framebuffer_width() >= 800 ? 2 : 1),  // 5×7 glyphs doubled on wide windows
        controller_(pose_of(scene_)),
        reloader_(stamp_file(args.scene)) {
    settings_.stereo = args.runtime.stereo_mode;
    settings_.billboards = args.runtime.alignment.value_or(scene_.render.billboards);
    settings_.layer_scale = args.runtime.layer_scale.value_or(scene_.render.layer_scale);
    settings_.overlay = !args.no_overlay;
    runtime_ = make_runtime(scene_);
  }

  // Runs until the window closes, Esc, or args.frames frames; returns the summary.
  nlohmann::json run(const std::vector<ScriptedEdit>& edits,
                     const std::vector<ScriptedPress>& presses) {
    using clock = std::chrono::steady_clock;
    const auto t0 = clock::now();
    auto last_overlay_refresh = t0;
    double runtime_seconds = 0, window_seconds = 0;
    while (!window_.should_close() && (args_.frames == 0 || frame_ < uint64_t(args_.frames))) {
      const auto frame_start = clock::now();
      // Paused with nothing to redraw: wait for input (up to 50 ms) instead of spinning.
      const bool idle = settings_.paused && settings_.pending_steps == 0 && !needs_redraw_;
      if (idle && args_.frames == 0) window_.wait_events(0.05);
      else window_.poll_events();
      for (const ScriptedPress& p : presses)
        if (p.frame == frame_) window_.inject_key_press({p.key, 0});
      handle_input(std::chrono::duration<float>(frame_start - previous_frame_).count());
      previous_frame_ = frame_start;
      if (quit_) break;
      for (const ScriptedEdit& e : edits)
        if (e.frame == frame_) write_in_place(args_.scene, e.content);
      const FileStamp stamp = stamp_file(args_.scene);
      if (reload_requested_ || reloader_.changed(stamp)) reload(stamp);
      reload_requested_ = false;

      const auto sim_start = clock::now();
      apply_camera();
      if (!settings_.paused) {
        runtime_->step();
      } else if (settings_.pending_steps > 0) {
        --settings_.pending_steps;
        runtime_->step();
      } else if (needs_redraw_) {
        runtime_->redraw();  // paused, but the camera moved or the runtime is new
      }
      needs_redraw_ = false;
      const auto sim_end = clock::now();
      runtime_seconds += std::chrono::duration<double>(sim_end - sim_start).count();
      smooth_system_times();

      // The frame rate shown is refreshed four times a second so that it can be read.
      const double since = std::chrono::duration<double>(sim_end - last_overlay_refresh).count();
      if (since >= 0.25 || frame_ == 0) {
        const uint64_t frames_done = frame_ + 1 - overlay_frame_mark_;
        shown_fps_ = frame_ == 0 ? 0.0 : double(frames_done) / since;
        shown_frame_ms_ = frame_ == 0 ? 0.0 : since * 1000.0 / double(frames_done);
        overlay_frame_mark_ = frame_ + 1;
        last_overlay_refresh = sim_end;
        overlay_stale_ = true;
      }
      present();
      const bool last = args_.frames > 0 && frame_ + 1 == uint64_t(args_.frames);
      if (last && !args_.screenshot.empty()) save_screenshot();
      window_.swap_buffers();
      window_seconds += std::chrono::duration<double>(clock::now() - sim_end).count();
      ++frame_;
    }
    if (args_.frames == 0 && !args_.screenshot.empty() && frame_ > 0) {
      // Closed by the user: the back buffer is gone after the swap, so draw the last frame again.
      present();
      save_screenshot();
    }
    const double seconds = std::chrono::duration<double>(clock::now() - t0).count();
    nlohmann::json reloads = nlohmann::json::array();
    for (const ReloadEvent& e : reloader_.history()) {
      nlohmann::json j = {{"frame", e.frame}, {"ok", e.ok}};
      if (!e.ok) j["error"] = e.error;
      reloads.push_back(j);
    }
    return {{"scene", args_.scene},
            {"name", scene_.name},
            {"frames", frame_},
            {"width", window_.framebuffer_width()},
            {"height", window_.framebuffer_height()},
            {"seconds", seconds},
            {"fps", frame_ ? double(frame_) / seconds : 0.0},
            {"ms_per_frame", frame_ ? seconds * 1000.0 / double(frame_) : 0.0},
            {"runtime_ms_per_frame", frame_ ? runtime_seconds * 1000.0 / double(frame_) : 0.0},
            {"window_ms_per_frame", frame_ ? window_seconds * 1000.0 / double(frame_) : 0.0},
            {"particles", particle_count()},
            {"simulation_frame", runtime_->frame()},
            {"paused", settings_.paused},
            {"camera", name_of(controller_.mode())},
            {"billboards", name_of(settings_.billboards)},
            {"stereo", name_of(settings_.stereo)},
            {"layer_scale", settings_.layer_scale},
            {"screenshot", args_.screenshot},
            {"reloads", reloads},
            {"renderer", window_.description()}};
  }

 private:
  static CameraPose pose_of(const SceneDescription& s) {
    return {s.camera.position, s.camera.target, s.camera.up};
  }

  std::unique_ptr<SceneRuntime> make_runtime(const SceneDescription& scene) {
    RuntimeOptions o = args_.runtime;
    o.readback = false;
    o.width_override = args_.width;
    o.height_override = args_.height;
    o.stereo_mode = settings_.stereo;
    o.alignment = settings_.billboards;
    o.layer_scale = settings_.layer_scale;
    o.make_context_current = [w = &window_] { w->make_current(); };
    return std::make_unique<SceneRuntime>(scene, o);
  }

  static void write_in_place(const std::string& path, const std::string& content) {
    std::ofstream f(path, std::ios::binary | std::ios::trunc);
    f << content;
    if (!f) throw std::runtime_error(path + ": cannot write the scripted edit (--replace-at)");
  }

  void reload(const FileStamp& stamp) {
    try {
      SceneDescription scene = load_scene(args_.scene);
      std::unique_ptr<SceneRuntime> runtime = make_runtime(scene);
      runtime_ = std::move(runtime);
      needs_redraw_ = true;
      scene_ = std::move(scene);
      if (!camera_moved_) controller_ = ViewController(pose_of(scene_));
      else camera_dirty_ = true;
      reloader_.succeeded(stamp, frame_);
      overlay_stale_ = true;
      std::fprintf(stderr, "pyro view: frame %llu: reloaded %s\n", (unsigned long long)frame_,
                   args_.scene.c_str());
    } catch (const UserError& e) {
      reload_failed(stamp, error_text(e));
    } catch (const gpu::GpuError& e) {
      reload_failed(stamp, error_text(e));
    }
  }

  void reload_failed(const FileStamp& stamp, const std::string& message) {
    reloader_.failed(stamp, frame_, message);
    overlay_stale_ = true;
    std::fprintf(stderr, "pyro view: frame %llu: reload failed, keeping the last good scene: %s\n",
                 (unsigned long long)frame_, message.c_str());
  }

  // A new runtime for changed render settings, at the same simulation frame.
  void rebuild(const ViewerSettings& previous) {
    try {
      const uint64_t at = runtime_->frame();
      std::unique_ptr<SceneRuntime> runtime = make_runtime(scene_);
      while (runtime->frame() < at) runtime->simulate_step();
      runtime_ = std::move(runtime);
      needs_redraw_ = true;
      camera_dirty_ = true;
      notice_.clear();
    } catch (const std::exception& e) {
      settings_ = previous;
      notice_ = error_text(e);
    }
  }

  void handle_input(float dt) {
    for (const gpu::KeyPress& k : window_.take_key_presses()) {
      const std::optional<ViewerAction> action = action_for_key(k.key, k.mods);
      if (!action) continue;
      const ViewerSettings previous = settings_;
      const ViewerEffect effect = apply_action(settings_, *action);
      overlay_stale_ = true;
      if (effect.quit) quit_ = true;
      if (effect.toggle_camera_mode) controller_.toggle_mode();
      if (effect.reload_scene) reload_requested_ = true;
      if (effect.rebuild_runtime) rebuild(previous);
    }
    double dx = 0, dy = 0;
    window_.take_drag(dx, dy);
    const double scroll = window_.take_scroll();
    HeldKeys held;
    held.forward = window_.key_down(GLFW_KEY_W);
    held.back = window_.key_down(GLFW_KEY_S);
    held.left = window_.key_down(GLFW_KEY_A);
    held.right = window_.key_down(GLFW_KEY_D);
    held.up = window_.key_down(GLFW_KEY_E);
    held.down = window_.key_down(GLFW_KEY_Q);
    held.fast = window_.key_down(GLFW_KEY_LEFT_SHIFT) || window_.key_down(GLFW_KEY_RIGHT_SHIFT);
    const glm::vec3 move = move_direction(held);
    const bool camera_input = dx != 0 || dy != 0 || scroll != 0 || move != glm::vec3(0.0f);
    if (camera_input && !camera_moved_) {
      // The first touch takes the camera from where the scene put it (its scripted orbit may
      // have moved it since the start), keeping the chosen mode and speed.
      const CameraControl mode = controller_.mode();
      world_camera_pose_into(controller_);
      controller_.set_mode(mode);
    }
    if (dx != 0 || dy != 0) controller_.drag(float(dx), float(dy));
    if (scroll != 0) controller_.scroll(float(scroll));
    if (move != glm::vec3(0.0f)) controller_.move(move * move_speed_factor(held), std::min(dt, 0.1f));
    if (camera_input) {
      camera_moved_ = true;
      camera_dirty_ = true;
    }
  }

  void world_camera_pose_into(ViewController& controller) {
    runtime_->world().each<Camera>([&](Camera& c) {
      if (c.position != c.target) controller = ViewController({c.position, c.target, c.up});
    });
  }

  // Once the user has moved the camera it is theirs: the scene's scripted orbit stops.
  void apply_camera() {
    if (!camera_moved_ || !camera_dirty_) return;
    needs_redraw_ = true;
    ecs::World& world = runtime_->world();
    std::vector<ecs::Entity> orbiting;
    world.each<CameraOrbit>([&](ecs::Entity e, CameraOrbit&) { orbiting.push_back(e); });
    for (ecs::Entity e : orbiting) world.remove<CameraOrbit>(e);
    const CameraPose pose = controller_.pose();
    world.each<Camera>([&](Camera& c) {
      c.position = pose.position;
      c.target = pose.target;
      c.up = pose.up;
    });
    camera_dirty_ = false;
  }

  size_t particle_count() {
    const auto* lists = runtime_->world().try_resource<EyeDrawLists>();
    return lists && !lists->eyes.empty() ? lists->eyes[0].size() : 0;
  }

  void smooth_system_times() {
    for (const ecs::SystemStats& s : runtime_->schedule().stats()) {
      auto [it, fresh] = system_ms_.try_emplace(s.name, s.last_ms);
      if (!fresh) it->second = 0.9 * it->second + 0.1 * s.last_ms;
    }
  }

  std::vector<OverlayLine> overlay() {
    OverlayInfo info;
    info.scene = args_.scene;
    info.fps = shown_fps_;
    info.frame_ms = shown_frame_ms_;
    info.frame = runtime_->frame();
    info.particles = particle_count();
    for (const ecs::SystemStats& s : runtime_->schedule().stats())
      info.system_ms.emplace_back(s.name, system_ms_[s.name]);
    info.stereo = upper_case(name_of(settings_.stereo));
    info.billboards = upper_case(name_of(settings_.billboards));
    info.layer_scale = layer_scale_name(settings_.layer_scale);
    info.camera = upper_case(name_of(controller_.mode()));
    info.paused = settings_.paused;
    info.error = reloader_.showing_error() ? reloader_.error() : notice_;
    info.help = settings_.help;
    const int columns = std::max(window_.framebuffer_width() / text_.cell_width() - 2, 8);
    return overlay_lines(info, columns);
  }

  // The runtime's output, letterboxed into the window, then the overlay.
  void present() {
    window_.make_current();
    const int ww = window_.framebuffer_width(), wh = window_.framebuffer_height();
    const gpu::RenderTarget& out = runtime_->output_target();
    // Byte copies: no sRGB decode on read or encode on write (the output is already encoded).
    glDisable(GL_FRAMEBUFFER_SRGB);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, ww, wh);
    glClearColor(0.05f, 0.05f, 0.05f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    const double scale = std::min(double(ww) / out.width(), double(wh) / out.height());
    const int w = int(out.width() * scale + 0.5), h = int(out.height() * scale + 0.5);
    const int x0 = (ww - w) / 2, y0 = (wh - h) / 2;
    glBlitNamedFramebuffer(out.framebuffer(), 0, 0, 0, out.width(), out.height(), x0, y0, x0 + w,
                           y0 + h, GL_COLOR_BUFFER_BIT,
                           w == out.width() && h == out.height() ? GL_NEAREST : GL_LINEAR);
    if (settings_.overlay) {
      // The text is laid out again only when something in it changed (four times a second for
      // the rates, or after a key or a reload), so a steady overlay costs one draw call.
      if (overlay_stale_ || ww != overlay_width_) text_.set_lines(overlay());
      overlay_stale_ = false;
      overlay_width_ = ww;
      text_.draw(ww, wh);
    }
    glEnable(GL_FRAMEBUFFER_SRGB);
  }

  void save_screenshot() {
    const int w = window_.framebuffer_width(), h = window_.framebuffer_height();
    std::vector<uint8_t> rows(size_t(w) * size_t(h) * 3);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, w, h, GL_RGB, GL_UNSIGNED_BYTE, rows.data());
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    std::vector<uint8_t> top_down(rows.size());
    const size_t stride = size_t(w) * 3;
    for (int y = 0; y < h; ++y)
      std::copy_n(rows.begin() + std::ptrdiff_t(size_t(h - 1 - y) * stride), stride,
                  top_down.begin() + std::ptrdiff_t(size_t(y) * stride));
    write_png(args_.screenshot, w, h, 3, top_down);  // atomically (engine/io/png_file.h)
  }

  const ViewArgs& args_;
  SceneDescription scene_;
  gpu::WindowContext window_;
  TextRenderer text_;
  ViewController controller_;
  SceneReloader reloader_;
  ViewerSettings settings_;
  std::unique_ptr<SceneRuntime> runtime_;
  std::map<std::string, double> system_ms_;
  std::string notice_;  // a render-setting change the runtime refused
  uint64_t frame_ = 0;
  uint64_t overlay_frame_mark_ = 0;
  double shown_fps_ = 0, shown_frame_ms_ = 0;
  std::chrono::steady_clock::time_point previous_frame_ = std::chrono::steady_clock::now();
  bool camera_moved_ = false, camera_dirty_ = false;
  bool reload_requested_ = false, quit_ = false;
  bool overlay_stale_ = true;
  bool needs_redraw_ = true;  // paused frames draw only after a change
  int overlay_width_ = 0;
};

void run_view(const ViewArgs& a) {
  // Everything the user can get wrong is checked before the window opens.
  const std::vector<ScriptedEdit> edits = parse_edits(a.replace_at);
  const std::vector<ScriptedPress> presses = parse_presses(a.press_at);
  if (!a.screenshot.empty()) {
    namespace fs = std::filesystem;
    const fs::path parent = fs::path(a.screenshot).parent_path();
    std::error_code ec;
    if (!parent.empty() && !fs::is_directory(parent, ec))
      throw UserError(a.screenshot, "--screenshot", "expected a PNG path in an existing folder");
    if (fs::is_directory(a.screenshot, ec))
      throw UserError(a.screenshot, "--screenshot", "expected a PNG file name, found a folder");
  }
  SceneDescription scene = load_scene(a.scene);
  Viewer viewer(a, std::move(scene));
  const nlohmann::json summary = viewer.run(edits, presses);
  if (a.json) {
    std::printf("%s\n", summary.dump().c_str());
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
  cmd->add_flag("--no-overlay", args->no_overlay, "Start with the overlay hidden (O shows it)");
  cmd->add_option("--replace-at", args->replace_at,
                  "FRAME:FILE: at that frame, write FILE's content over the scene file (as an "
                  "editor would; the hot reload picks it up). Repeatable; for tests and demos");
  cmd->add_option("--press-at", args->press_at,
                  "FRAME:KEY: press KEY (1-7, B, L, N, R, O, H, SPACE, TAB, ESC) at that frame. "
                  "Repeatable; for tests and demos");
  cmd->add_flag("--json", args->json, "Print a JSON summary as the last line");
  add_render_options(cmd, args->runtime);
  cmd->callback([args] { run_view(*args); });
}

}  // namespace pyro::cli
