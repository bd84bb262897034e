#include "tools/viewer/viewer.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <utility>

#include "components/camera.h"
#include "components/camera_orbit.h"
#include "engine/core/enum_names.h"
#include "engine/core/user_error.h"
#include "engine/gpu/current_context.h"
#include "engine/gpu/gpu_error.h"
#include "engine/gpu/window_context.h"
#include "engine/io/png_file.h"
#include "engine/math/view_controller.h"
#include "tools/authoring/scene_document.h"
#include "systems/runtime/open_scene/open_scene.h"
#include "systems/runtime/scene/scene_keys.h"
#include "systems/runtime/scene_runtime/particle_counts.h"
#include "systems/runtime/scene_runtime/scene_asset_cache.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"
#include "tools/viewer/frame_time_history.h"
#include "tools/viewer/inspector_panel.h"
#include "tools/viewer/panel_column.h"
#include "tools/viewer/panel_layout.h"
#include "tools/viewer/profiler_panel.h"
#include "tools/viewer/scene_reloader.h"
#include "tools/viewer/status_panel.h"
#include "tools/viewer/stereo_panel.h"
#include "tools/viewer/viewer_gui.h"
#include "tools/viewer/viewer_keys.h"
#include "tools/viewer/viewer_overlay.h"
#include "tools/viewer/viewer_settings.h"
#include "tools/viewer/window_image.h"

namespace pyro {

namespace {

using Clock = std::chrono::steady_clock;

// The panels' font and widget scale (1: 13-pixel text).
constexpr float kGuiScale = 1.0f;

// The window opens at the frame's size beside the panel column (panel_layout.h); with the panels
// off (--no-overlay), at the frame's own size.
WindowSize opening_size(const ViewerOptions& o, const SceneDescription& s) {
  const int width = output_width(o.width > 0 ? o.width : s.width, o.runtime.stereo_mode);
  const int height = o.height > 0 ? o.height : s.height;
  return viewer_window_size(width, height, o.overlay ? panel_column_width(kGuiScale) : 0.0f);
}

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
        window_(opening_size(o_, scene_).width, opening_size(o_, scene_).height,
                "pyro view - " + o_.scene + " - " + key_help_title()),
        gui_(window_.glfw_window(), kGuiScale),
        controller_(pose_of(scene_)),
        reloader_(stamp_file(o_.scene)),
        document_(SceneDocument::open(o_.scene)),
        inspector_(o_.inspect),
        panels_(!o_.inspect.empty()) {
    for (const std::string& name : o_.expand) panels_.expand(name);
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
      save_screenshot(o_.screenshot);
    }
    if (!o_.save_as.empty()) {
      document_.save_as(o_.save_as);
      note("saved " + o_.save_as);
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
    const FileStamp stamp = stamp_file(document_.path());
    if (reload_requested_ || reloader_.changed(stamp)) reload(stamp);
    reload_requested_ = false;
    run_script();
    take_requests();

    const auto sim_start = Clock::now();
    advance_runtime();
    const auto sim_end = Clock::now();
    runtime_seconds_ += std::chrono::duration<double>(sim_end - sim_start).count();
    record_frame_times();
    refresh_rates(sim_end);
    present();
    if (pending_rebuild_) {  // a panel changed a render setting
      const ViewerSettings previous = *pending_rebuild_;
      pending_rebuild_.reset();
      rebuild(previous);
    }
    const bool last = o_.frames > 0 && frame_ + 1 == uint64_t(o_.frames);
    if (last && !o_.screenshot.empty()) save_screenshot(o_.screenshot);
    for (const ViewerScreenshot& shot : o_.screenshots)
      if (shot.frame == frame_) save_screenshot(shot.file);
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
                        {"edits", edits_applied_},
                        {"modified", document_.modified()},
                        {"assets", asset_counters_json()},
                        {"layout", layout_json()},
                        {"renderer", window_.description()}};
    if (quality_) j["quality"] = quality_pick_summary(*quality_);
    return j;
  }

  std::vector<std::pair<std::string, uint64_t>> asset_counters() const {
    const SceneAssetCounters& c = assets_.counters();
    return {{"volumes_loaded", c.volumes_loaded},       {"volumes_reused", c.volumes_reused},
            {"flipbooks_prepared", c.flipbooks_prepared}, {"flipbooks_reused", c.flipbooks_reused},
            {"flipbooks_baked", c.flipbooks_baked}};
  }

  nlohmann::json asset_counters_json() const {
    nlohmann::json j = nlohmann::json::object();
    for (const auto& [name, count] : asset_counters()) j[name] = count;
    return j;
  }

  // The scene through the engine's front door (systems/runtime/open_scene/open_scene.h) with the
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
    o.asset_cache = &assets_;
    o.profile = gpu_profiling_;
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
      SceneDocument document = SceneDocument::open(document_.path());
      OpenedScene opened = open(document.description(), std::nullopt, [this](const std::string& text) { note(text); });
      if (document_.modified()) note("the file changed on disk: the inspector's unsaved edits are replaced by it");
      document_ = std::move(document);
      scene_ = std::move(opened.description);
      take(std::move(opened));
      needs_redraw_ = true;
      if (!camera_moved_) controller_ = ViewController(pose_of(scene_));
      else camera_dirty_ = true;
      reloader_.succeeded(stamp, frame_);
      note("reloaded " + document_.path());
    } catch (const UserError& e) {
      reload_failed(stamp, e.what());
    } catch (const gpu::GpuError& e) {
      reload_failed(stamp, e.what());
    }
  }

  void reload_failed(const FileStamp& stamp, const std::string& message) {
    reloader_.failed(stamp, frame_, message);
    panels_[ViewerPanel::status].expanded = true;  // where the message is
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
      panels_[ViewerPanel::status].expanded = true;
    }
  }

  void handle_keys() {
    // Keys typed into a panel's text field are the panel's.
    const bool typing = settings_.overlay && gui_.wants_keyboard();
    for (const gpu::KeyPress& k : window_.take_key_presses()) {
      if (typing && k.key != GLFW_KEY_ESCAPE) continue;
      const std::optional<ViewerAction> action = action_for_key(k.key, k.mods);
      if (!action) continue;
      const ViewerSettings previous = settings_;
      const ViewerEffect effect = apply_action(settings_, *action);
      if (settings_.help && !previous.help) panels_[ViewerPanel::status].expanded = true;
      if (effect.quit) quit_ = true;
      if (effect.toggle_camera_mode) controller_.toggle_mode();
      if (effect.reload_scene) reload_requested_ = true;
      if (effect.rebuild_runtime) rebuild(previous);
      if (effect.undo || effect.redo || effect.save) {
        InspectorRequest r;
        r.undo = effect.undo;
        r.redo = effect.redo;
        r.save = effect.save;
        requests_.push_back(r);
      }
    }
  }

  // The scripted sets and undos of this frame (pyro view --set-at, --undo-at): refused ones end
  // the session with the document's message.
  void run_script() {
    for (const ViewerSet& set : o_.sets) {
      if (set.frame != frame_) continue;
      document_.set(set.pointer, set.value);
      after_document_change();
    }
    for (uint64_t undo_frame : o_.undos) {
      if (undo_frame != frame_) continue;
      if (!document_.can_undo())
        throw UserError(o_.scene, "--undo-at " + std::to_string(undo_frame), "expected an edit to undo, found none");
      document_.undo();
      after_document_change();
    }
  }

  // What the panels and the Ctrl keys asked for last frame; a refused one is shown in the
  // inspector and changes nothing.
  void take_requests() {
    std::vector<InspectorRequest> requests = std::move(requests_);
    requests_.clear();
    for (const InspectorRequest& r : requests) {
      try {
        apply_request(r);
      } catch (const std::exception& e) {
        inspector_status_.error = e.what();
      }
    }
  }

  void apply_request(const InspectorRequest& r) {
    if (!r.error.empty()) throw UserError(document_.path(), "", r.error);
    if (r.edit) document_.set(r.edit->pointer, r.edit->value, r.edit->coalesce);
    if (r.undo && document_.can_undo()) document_.undo();
    if (r.redo && document_.can_redo()) document_.redo();
    if (r.edit || r.undo || r.redo) {
      inspector_status_ = {};
      after_document_change();
    }
    if (r.save) save_document(document_.path());
    if (!r.save_as.empty()) save_document(r.save_as);
  }

  void save_document(const std::string& path) {
    if (path == document_.path()) document_.save();
    else document_.save_as(path);
    // The viewer's own write is not an edit from outside to reload.
    reloader_.accept(stamp_file(document_.path()));
    inspector_status_ = {};
    inspector_status_.message = "saved " + document_.path();
    note(inspector_status_.message);
  }

  // The document changed: a new runtime from its description, at the same simulation frame. The
  // asset cache keeps every volume and flipbook the change did not touch, so an emitter's rate
  // re-imports and re-bakes nothing. A scene the runtime refuses takes the change back.
  void after_document_change() {
    ++edits_applied_;
    const uint64_t at = runtime_->frame();
    const bool quality_changed = touches(document_.last_changed(), "/quality");
    try {
      OpenedScene opened = open(document_.description(), quality_changed ? std::nullopt : quality_, {});
      while (opened.runtime->frame() < at) opened.runtime->simulate_step();
      scene_ = std::move(opened.description);
      take(std::move(opened));
    } catch (const std::exception&) {
      if (document_.can_undo()) document_.undo();
      throw;
    }
    needs_redraw_ = true;
    if (!camera_moved_) controller_ = ViewController(pose_of(scene_));
    else camera_dirty_ = true;
  }

  static bool touches(const std::vector<std::string>& pointers, const std::string& prefix) {
    for (const std::string& p : pointers)
      if (p.rfind(prefix, 0) == 0) return true;
    return false;
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
    double scroll = window_.take_scroll();
    if (settings_.overlay && gui_.wants_mouse()) dx = dy = scroll = 0;  // a panel's drag or wheel
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

  // The schedule's milliseconds per system, smoothed for the status line and kept over the last
  // seconds for the profiler's plots, with the GPU passes' fragments when profiling.
  void record_frame_times() {
    const double t = std::chrono::duration<double>(Clock::now() - started_).count();
    for (const ecs::SystemStats& s : runtime_->schedule().stats()) {
      auto [it, fresh] = system_ms_.try_emplace(s.name, s.last_ms);
      if (!fresh) it->second = 0.9 * it->second + 0.1 * s.last_ms;
      system_history_.add(s.name, t, s.last_ms);
    }
    for (const TraceSpan& span : runtime_->take_trace())
      if (span.track == TraceTrack::gpu && span.fragments >= 0)
        fragment_history_.add(span.name, t, double(span.fragments));
    system_history_.trim(t);
    fragment_history_.trim(t);
  }

  OverlayInfo status_info() {
    OverlayInfo info;
    info.scene = document_.path();
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
    return info;
  }

  // The panels, in their column: status (rates, modes, a failed reload's message, the keys),
  // inspector, profiler and stereo. What they ask for is applied at the start of the next frame.
  void draw_panels() {
    const OverlayInfo info = status_info();
    const PanelRect column = window_split(window_units()).column;
    const std::vector<OverlayLine> lines = overlay_lines(info, status_panel_columns(column.width));
    place_panels(column, lines.size(), !info.help && info.error.empty());
    draw_status_panel(overlay_header(info), lines, panels_[ViewerPanel::status]);
    InspectorStatus status = inspector_status_;
    status.file = document_.path();
    status.modified = document_.modified();
    status.can_undo = document_.can_undo();
    status.can_redo = document_.can_redo();
    requests_.push_back(
        inspector_.draw(document_.tree(), scene_keys(), status, panels_[ViewerPanel::inspector]));
    StereoRequest stereo =
        draw_stereo_panel(settings_.stereo, document_.tree(), panels_[ViewerPanel::stereo]);
    requests_.push_back(std::move(stereo.keys));
    if (stereo.mode) {
      const ViewerSettings previous = settings_;
      settings_.stereo = *stereo.mode;
      pending_rebuild_ = previous;
    }
    if (draw_profiler_panel(profiler_view(), panels_[ViewerPanel::profiler]).toggle_gpu_profiling) {
      gpu_profiling_ = !gpu_profiling_;
      pending_rebuild_ = settings_;
    }
  }

  // This frame's places in `column`: each panel asks for the height it would like expanded. The
  // status asks for its lines, up to a quarter of the column unless they show the key help or an
  // error; the inspector, whose tree is long, for the whole column.
  void place_panels(const PanelRect& column, size_t status_lines, bool status_capped) {
    const float header = docked_panel_header_height();
    float status = status_panel_height(status_lines);
    if (status_capped) status = std::min(status, std::max(header, std::floor(column.height / 4)));
    panels_.place(column, {status, column.height, 300 * kGuiScale, 140 * kGuiScale}, header);
  }

  // The window's size in the units the panels are laid out in (GLFW's screen coordinates).
  std::pair<float, float> window_units() const {
    int w = 0, h = 0;
    glfwGetWindowSize(window_.glfw_window(), &w, &h);
    return {float(w), float(h)};
  }

  // The frame's part and the panels' column of a window `size` (window_units()) wide and high.
  // The column stays while O hides the panels, so that the frame keeps its place; a window opened
  // without panels (--no-overlay) makes room for them when O shows them.
  WindowSplit window_split(std::pair<float, float> size) const {
    const bool column = o_.overlay || settings_.overlay;
    return split_window(size.first, size.second, column ? panel_column_width(kGuiScale) : 0.0f);
  }

  // Where the panels were last placed and the frame drawn, for --json (window pixels).
  nlohmann::json layout_json() const {
    return {{"view", panel_rect_json(view_)},
            {"panels", panels_.to_json()},
            {"shown", settings_.overlay}};
  }

  ProfilerView profiler_view() {
    ProfilerView v;
    v.fps = shown_fps_;
    v.frame_ms = shown_frame_ms_;
    v.frame = runtime_->frame();
    v.drawn = drawn_particles(runtime_->world());
    v.census = count_particles(runtime_->world());
    v.systems = &system_history_;
    v.fragments = &fragment_history_;
    v.asset_counters = asset_counters();
    v.gpu_profiling = gpu_profiling_;
    return v;
  }

  // The runtime's output beside the panels' column, scaled to fit its part, then the panels.
  void present() {
    window_.make_current();
    const int ww = window_.framebuffer_width(), wh = window_.framebuffer_height();
    const std::pair<float, float> units = window_units();
    const float r = units.first > 0 ? float(ww) / units.first : 1.0f;  // 1 but on scaled displays
    const PanelRect area = window_split(units).view;
    const gpu::RenderTarget& out = runtime_->output_target();
    view_ = fit_frame({area.x * r, area.y * r, area.width * r, area.height * r}, out.width(),
                      out.height());
    {
      const SrgbWritesOff bytes;
      present_frame(out, view_, ww, wh);
    }
    if (!settings_.overlay) return;
    gui_.begin_frame();
    draw_panels();
    gui_.render();
  }

  void save_screenshot(const std::string& file) {
    const int w = window_.framebuffer_width(), h = window_.framebuffer_height();
    write_png(file, w, h, 3, read_window_rgb(w, h));  // atomically (engine/io/png_file.h)
  }

  const ViewerOptions& o_;
  SceneDescription scene_;
  gpu::WindowContext window_;
  ViewerGui gui_;
  ViewController controller_;
  SceneReloader reloader_;
  SceneDocument document_;  // the file as the inspector edits it
  SceneAssetCache assets_;  // volumes and flipbooks kept across the runtimes the edits make
  ViewerSettings settings_;
  bool layer_scale_chosen_ = false;  // by --layer-scale or the L key
  bool gpu_profiling_ = false;       // the profiler panel's GPU passes
  std::unique_ptr<SceneRuntime> runtime_;
  std::optional<QualityPick> quality_;  // the pick runtime_ runs with (scene key quality.max_rmse)
  InspectorPanel inspector_;
  PanelColumn panels_;
  PanelRect view_;  // where the frame was last drawn
  InspectorStatus inspector_status_;
  std::vector<InspectorRequest> requests_;
  std::optional<ViewerSettings> pending_rebuild_;  // the settings before a panel changed them
  std::map<std::string, double> system_ms_;
  FrameTimeHistory system_history_, fragment_history_;
  std::string notice_;  // a render-setting change the runtime refused
  uint64_t frame_ = 0;
  uint64_t edits_applied_ = 0;
  uint64_t overlay_frame_mark_ = 0;
  double shown_fps_ = 0, shown_frame_ms_ = 0;
  double runtime_seconds_ = 0, window_seconds_ = 0;
  const Clock::time_point started_ = Clock::now();
  Clock::time_point previous_frame_ = Clock::now();
  Clock::time_point last_overlay_refresh_{};
  bool camera_moved_ = false, camera_dirty_ = false;
  bool reload_requested_ = false, quit_ = false;
  bool needs_redraw_ = true;  // paused frames draw only after a change
};

}  // namespace

nlohmann::json run_viewer(const ViewerOptions& options, SceneDescription scene) {
  return Viewer(options, std::move(scene)).run();
}

}  // namespace pyro
