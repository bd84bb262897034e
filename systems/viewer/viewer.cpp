#include "systems/viewer/viewer.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>

#include "components/camera.h"
#include "components/camera_orbit.h"
#include "engine/core/enum_names.h"
#include "engine/core/user_error.h"
#include "engine/gpu/current_context.h"
#include "engine/gpu/gpu_error.h"
#include "engine/gpu/window_context.h"
#include "engine/io/png_file.h"
#include "engine/math/view_controller.h"
#include "systems/open_scene/open_scene.h"
#include "systems/scene_runtime/particle_counts.h"
#include "systems/scene_runtime/scene_runtime.h"
#include "systems/viewer/scene_reloader.h"
#include "systems/viewer/viewer_keys.h"
#include "systems/viewer/viewer_overlay.h"
#include "systems/viewer/viewer_settings.h"
#include "systems/viewer/viewer_text_renderer.h"
#include "systems/viewer/window_image.h"

namespace pyro {

namespace {

using Clock = std::chrono::steady_clock;

CameraPose pose_of(const SceneDescription& s) {
  return {s.camera.position, s.camera.target, s.camera.up};
}

void write_in_place(const std::string& path, const std::string& content) {
  std::ofstream f(path, std::ios::binary | std::ios::trunc);
  f << content;
  if (!f) throw std::runtime_error(path + ": cannot write the scripted edit (--replace-at)");
}

class Viewer {
 public:
  Viewer(const ViewerOptions& options, SceneDescription scene)
      : o_(options),
        scene_(std::move(scene)),
        window_(output_width(o_.width > 0 ? o_.width : scene_.width, o_.runtime.stereo_mode),
                o_.height > 0 ? o_.height : scene_.height,
                "pyro view - " + o_.scene + " - " + key_help_title()),
        text_(window_.framebuffer_width() >= 800 ? 2 : 1),  // 5×7 glyphs doubled on wide windows
        controller_(pose_of(scene_)),
        reloader_(stamp_file(o_.scene)) {
    settings_.stereo = o_.runtime.stereo_mode;
    settings_.billboards = o_.runtime.alignment.value_or(scene_.render.billboards);
    settings_.layer_scale = o_.runtime.layer_scale.value_or(scene_.render.layer_scale);
    settings_.overlay = o_.overlay;
    layer_scale_chosen_ = o_.runtime.layer_scale.has_value();
    take(open(scene_, std::nullopt, o_.on_note));
  }

  nlohmann::json run() {
    const auto t0 = Clock::now();
    last_overlay_refresh_ = t0;
    while (!window_.should_close() && (o_.frames == 0 || frame_ < uint64_t(o_.frames))) {
      if (!one_frame()) break;
      ++frame_;
    }
    if (o_.frames == 0 && !o_.screenshot.empty() && frame_ > 0) {
      // Closed by the user: the back buffer is gone after the swap, so draw the last frame again.
      present();
      save_screenshot();
    }
    return summary(std::chrono::duration<double>(Clock::now() - t0).count());
  }

 private:
  // Input, reloads, the runtime's step, the window's image. False: quit.
  bool one_frame() {
    const auto frame_start = Clock::now();
    // Paused with nothing to redraw: wait for input (up to 50 ms) instead of spinning.
    const bool idle = settings_.paused && settings_.pending_steps == 0 && !needs_redraw_;
    if (idle && o_.frames == 0) window_.wait_events(0.05);
    else window_.poll_events();
    for (const ViewerPress& p : o_.presses)
      if (p.frame == frame_) window_.inject_key_press({p.key, 0});
    handle_input(std::chrono::duration<float>(frame_start - previous_frame_).count());
    previous_frame_ = frame_start;
    if (quit_) return false;
    for (const ViewerEdit& e : o_.edits)
      if (e.frame == frame_) write_in_place(o_.scene, e.content);
    const FileStamp stamp = stamp_file(o_.scene);
    if (reload_requested_ || reloader_.changed(stamp)) reload(stamp);
    reload_requested_ = false;

    const auto sim_start = Clock::now();
    advance_runtime();
    const auto sim_end = Clock::now();
    runtime_seconds_ += std::chrono::duration<double>(sim_end - sim_start).count();
    smooth_system_times();
    refresh_rates(sim_end);
    present();
    const bool last = o_.frames > 0 && frame_ + 1 == uint64_t(o_.frames);
    if (last && !o_.screenshot.empty()) save_screenshot();
    window_.swap_buffers();
    window_seconds_ += std::chrono::duration<double>(Clock::now() - sim_end).count();
    return true;
  }

  void advance_runtime() {
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
  }

  // The frame rate shown is refreshed four times a second so that it can be read.
  void refresh_rates(Clock::time_point now) {
    const double since = std::chrono::duration<double>(now - last_overlay_refresh_).count();
    if (since < 0.25 && frame_ != 0) return;
    const uint64_t frames_done = frame_ + 1 - overlay_frame_mark_;
    shown_fps_ = frame_ == 0 ? 0.0 : double(frames_done) / since;
    shown_frame_ms_ = frame_ == 0 ? 0.0 : since * 1000.0 / double(frames_done);
    overlay_frame_mark_ = frame_ + 1;
    last_overlay_refresh_ = now;
    overlay_stale_ = true;
  }

  nlohmann::json summary(double seconds) {
    nlohmann::json reloads = nlohmann::json::array();
    for (const ReloadEvent& e : reloader_.history()) {
      nlohmann::json j = {{"frame", e.frame}, {"ok", e.ok}};
      if (!e.ok) j["error"] = e.error;
      reloads.push_back(j);
    }
    const double per_frame = frame_ ? 1000.0 / double(frame_) : 0.0;
    nlohmann::json j = {{"scene", o_.scene},
                        {"name", scene_.name},
                        {"frames", frame_},
                        {"width", window_.framebuffer_width()},
                        {"height", window_.framebuffer_height()},
                        {"seconds", seconds},
                        {"fps", frame_ ? double(frame_) / seconds : 0.0},
                        {"ms_per_frame", seconds * per_frame},
                        {"runtime_ms_per_frame", runtime_seconds_ * per_frame},
                        {"window_ms_per_frame", window_seconds_ * per_frame},
                        {"particles", drawn_particles(runtime_->world())},
                        {"simulation_frame", runtime_->frame()},
                        {"paused", settings_.paused},
                        {"camera", name_of(controller_.mode())},
                        {"billboards", name_of(settings_.billboards)},
                        {"stereo", name_of(settings_.stereo)},
                        {"layer_scale", settings_.layer_scale},
                        {"screenshot", o_.screenshot},
                        {"reloads", reloads},
                        {"renderer", window_.description()}};
    if (quality_) j["quality"] = quality_pick_summary(*quality_);
    return j;
  }

  // The scene through the engine's front door (systems/open_scene/open_scene.h) with the
  // viewer's settings: `scene` as held (none: the file read again), `pick` the quality pick
  // already made for it (none: the cache's, or measured now, for a scene with a target).
  OpenedScene open(std::optional<SceneDescription> scene, std::optional<QualityPick> pick,
                   const NoteSink& on_note) {
    OpenSceneOptions open;
    open.runtime = o_.runtime;
    RuntimeOptions& o = open.runtime;
    o.readback = false;
    o.width_override = o_.width;
    o.height_override = o_.height;
    o.stereo_mode = settings_.stereo;
    o.alignment = settings_.billboards;
    // A layer scale the user chose (--layer-scale, the L key) replaces the scene's and a pick's.
    o.layer_scale = layer_scale_chosen_ ? std::optional<float>(settings_.layer_scale) : std::nullopt;
    o.make_context_current = [w = &window_] { w->make_current(); };
    open.description = std::move(scene);
    open.quality = std::move(pick);
    open.on_note = on_note;
    // The pick is measured, or its cache keyed, on the shared headless context: the window's
    // context is released around it (engine/gpu/current_context.h), and made current again by
    // the runtime, or here when opening fails.
    open.on_pick = [](const std::optional<QualityPick>&) { gpu::release_current_egl_context(); };
    window_.release_current();
    try {
      return open_scene(o_.scene, open);
    } catch (...) {
      gpu::release_current_egl_context();
      window_.make_current();
      throw;
    }
  }

  // Runs `opened` from now on; until the user chooses a layer scale, the one shown is the one it
  // runs with (the scene's, or its quality pick's).
  void take(OpenedScene opened) {
    runtime_ = std::move(opened.runtime);
    quality_ = std::move(opened.quality);
    if (!layer_scale_chosen_) settings_.layer_scale = runtime_->resolved().settings.layer_scale;
  }

  void note(const std::string& text) const {
    if (o_.on_note) o_.on_note("frame " + std::to_string(frame_) + ": " + text);
  }

  void reload(const FileStamp& stamp) {
    try {
      OpenedScene opened = open(std::nullopt, std::nullopt, [this](const std::string& text) { note(text); });
      scene_ = std::move(opened.description);
      take(std::move(opened));
      needs_redraw_ = true;
      if (!camera_moved_) controller_ = ViewController(pose_of(scene_));
      else camera_dirty_ = true;
      reloader_.succeeded(stamp, frame_);
      overlay_stale_ = true;
      note("reloaded " + o_.scene);
    } catch (const UserError& e) {
      reload_failed(stamp, e.what());
    } catch (const gpu::GpuError& e) {
      reload_failed(stamp, e.what());
    }
  }

  void reload_failed(const FileStamp& stamp, const std::string& message) {
    reloader_.failed(stamp, frame_, message);
    overlay_stale_ = true;
    note("reload failed, keeping the last good scene: " + message);
  }

  // A new runtime for changed render settings, at the same simulation frame.
  // The scene's quality pick is kept (not noted again).
  void rebuild(const ViewerSettings& previous) {
    const bool chosen_before = layer_scale_chosen_;
    layer_scale_chosen_ = chosen_before || settings_.layer_scale != previous.layer_scale;
    try {
      const uint64_t at = runtime_->frame();
      OpenedScene opened = open(scene_, quality_, {});
      while (opened.runtime->frame() < at) opened.runtime->simulate_step();
      take(std::move(opened));
      needs_redraw_ = true;
      camera_dirty_ = true;
      notice_.clear();
    } catch (const std::exception& e) {
      settings_ = previous;
      layer_scale_chosen_ = chosen_before;
      notice_ = e.what();
    }
  }

  void handle_keys() {
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
  }

  HeldKeys held_keys() const {
    HeldKeys held;
    held.forward = window_.key_down(GLFW_KEY_W);
    held.back = window_.key_down(GLFW_KEY_S);
    held.left = window_.key_down(GLFW_KEY_A);
    held.right = window_.key_down(GLFW_KEY_D);
    held.up = window_.key_down(GLFW_KEY_E);
    held.down = window_.key_down(GLFW_KEY_Q);
    held.fast = window_.key_down(GLFW_KEY_LEFT_SHIFT) || window_.key_down(GLFW_KEY_RIGHT_SHIFT);
    return held;
  }

  void handle_input(float dt) {
    handle_keys();
    double dx = 0, dy = 0;
    window_.take_drag(dx, dy);
    const double scroll = window_.take_scroll();
    const HeldKeys held = held_keys();
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

  void smooth_system_times() {
    for (const ecs::SystemStats& s : runtime_->schedule().stats()) {
      auto [it, fresh] = system_ms_.try_emplace(s.name, s.last_ms);
      if (!fresh) it->second = 0.9 * it->second + 0.1 * s.last_ms;
    }
  }

  std::vector<OverlayLine> overlay() {
    OverlayInfo info;
    info.scene = o_.scene;
    info.fps = shown_fps_;
    info.frame_ms = shown_frame_ms_;
    info.frame = runtime_->frame();
    info.particles = drawn_particles(runtime_->world());
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

  // The runtime's output, letterboxed into the window, then the overlay (both as bytes).
  void present() {
    window_.make_current();
    const int ww = window_.framebuffer_width(), wh = window_.framebuffer_height();
    const SrgbWritesOff bytes;
    present_letterboxed(runtime_->output_target(), ww, wh);
    if (!settings_.overlay) return;
    // The text is laid out again only when something in it changed (four times a second for
    // the rates, or after a key or a reload), so a steady overlay costs one draw call.
    if (overlay_stale_ || ww != overlay_width_) text_.set_lines(overlay());
    overlay_stale_ = false;
    overlay_width_ = ww;
    text_.draw(ww, wh);
  }

  void save_screenshot() {
    const int w = window_.framebuffer_width(), h = window_.framebuffer_height();
    write_png(o_.screenshot, w, h, 3, read_window_rgb(w, h));  // atomically (engine/io/png_file.h)
  }

  const ViewerOptions& o_;
  SceneDescription scene_;
  gpu::WindowContext window_;
  TextRenderer text_;
  ViewController controller_;
  SceneReloader reloader_;
  ViewerSettings settings_;
  bool layer_scale_chosen_ = false;  // by --layer-scale or the L key
  std::unique_ptr<SceneRuntime> runtime_;
  std::optional<QualityPick> quality_;  // the pick runtime_ runs with (scene key quality.max_rmse)
  std::map<std::string, double> system_ms_;
  std::string notice_;  // a render-setting change the runtime refused
  uint64_t frame_ = 0;
  uint64_t overlay_frame_mark_ = 0;
  double shown_fps_ = 0, shown_frame_ms_ = 0;
  double runtime_seconds_ = 0, window_seconds_ = 0;
  Clock::time_point previous_frame_ = Clock::now();
  Clock::time_point last_overlay_refresh_{};
  bool camera_moved_ = false, camera_dirty_ = false;
  bool reload_requested_ = false, quit_ = false;
  bool overlay_stale_ = true;
  bool needs_redraw_ = true;  // paused frames draw only after a change
  int overlay_width_ = 0;
};

}  // namespace

nlohmann::json run_viewer(const ViewerOptions& options, SceneDescription scene) {
  return Viewer(options, std::move(scene)).run();
}

}  // namespace pyro
