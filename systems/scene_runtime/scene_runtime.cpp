#include "systems/scene_runtime/scene_runtime.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <stdexcept>

#include "components/camera.h"
#include "components/camera_orbit.h"
#include "components/emitter.h"
#include "components/explosion_shading.h"
#include "components/particle_dynamics.h"
#include "components/simulation_environment.h"
#include "components/cloud_volume.h"
#include "components/frame_clock.h"
#include "components/frame_image.h"
#include "components/gpu_frame.h"
#include "components/mesh_instance.h"
#include "components/particle_set.h"
#include "components/render_settings.h"
#include "components/stereo_camera.h"
#include "components/volume_source.h"
#include "engine/core/rng.h"
#include "engine/io/png_file.h"
#include "systems/scene/scene_budget.h"
#include "engine/math/footprint.h"
#include "systems/animation/drift_system.h"
#include "systems/animation/particle_animation_system.h"
#include "systems/animation/particle_prewarm.h"
#include "systems/billboard_render/billboard_render_system.h"
#include "systems/billboard_render/billboard_renderer.h"
#include "systems/camera/camera_system.h"
#include "systems/cloud_import/scene_volume.h"
#include "systems/composite/composite_systems.h"
#include "systems/composite/frame_targets.h"
#include "systems/emitter/cloud_emitter_system.h"
#include "systems/emitter/emitter_system.h"
#include "systems/flipbook_fire/flipbook_render_system.h"
#include "systems/flipbook_fire/flipbook_world.h"
#include "systems/mesh_render/mesh_render_system.h"
#include "systems/output/frame_readback_system.h"
#include "systems/sorting/depth_sort.h"

namespace pyro {

gpu::HeadlessContext& shared_headless_context() {
  static gpu::HeadlessContext context;
  return context;
}

SceneRuntime::SceneRuntime(const SceneDescription& scene, const RuntimeOptions& options)
    : scene_(scene),
      make_current_(options.make_context_current
                        ? options.make_context_current
                        : std::function<void()>([] { shared_headless_context().make_current(); })) {
  make_current_();
  // Every pass works in linear light: writes to sRGB targets are encoded and reads decoded.
  // (It changes nothing for float targets.)
  glEnable(GL_FRAMEBUFFER_SRGB);

  RenderSettings settings;
  settings.width = options.width_override > 0 ? options.width_override : scene.width;
  settings.height = options.height_override > 0 ? options.height_override : scene.height;
  settings.background = scene.background;
  settings.light_direction = scene.light.direction;
  settings.light_color = scene.light.color;
  settings.ambient = scene.light.ambient;
  settings.alignment = options.alignment.value_or(scene.render.billboards);
  settings.particles = options.particles.value_or(scene.render.particles);
  settings.layer_scale = options.layer_scale.value_or(scene.render.layer_scale);
  settings.frame_scale = options.frame_scale;
  settings.stereo_mode = options.stereo_mode;
  settings.shading = options.shading.value_or(scene.render.shading);
  settings.motion_blur = scene.render.motion_blur;
  world_.set_resource<RenderSettings>(settings);
  ExplosionShading shading;
  shading.fire_t_min = scene.render.fire_t_min;
  shading.fire_t_max = scene.render.fire_t_max;
  shading.fire_emission = scene.render.fire_emission;
  shading.fire_detail_range = scene.render.fire_detail_range;
  world_.set_resource<ExplosionShading>(shading);

  // Budgets (systems/scene/scene_budget.h): refused here, before any pool or target is allocated,
  // and again once the volumes' particles are known.
  GLint driver_max_texture = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &driver_max_texture);
  const int views = settings.stereo_mode == StereoMode::mono ? 1 : 2;
  const bool side_by_side = settings.stereo_mode == StereoMode::side_by_side ||
                            settings.stereo_mode == StereoMode::side_by_side_crossed ||
                            settings.stereo_mode == StereoMode::left_right;
  const auto check_budget = [&](uint64_t volume_particles) {
    check_scene_budget(scene,
                       estimate_scene_cost(scene, settings.width, settings.height, views,
                                           side_by_side ? 2 * settings.width : settings.width,
                                           volume_particles),
                       driver_max_texture);
  };
  check_budget(0);
  FrameClock clock;
  clock.dt = 1.0f / scene.frames_per_second;
  world_.set_resource<FrameClock>(clock);

  const ecs::Entity camera = world_.create();
  Camera& cam = world_.emplace<Camera>(camera);
  cam.position = scene.camera.position;
  cam.target = scene.camera.target;
  cam.up = scene.camera.up;
  cam.fov_y_deg = scene.camera.fov_y_deg;
  cam.near = scene.camera.near;
  cam.far = scene.camera.far;
  StereoCamera stereo;
  stereo.parameters.interocular = options.interocular.value_or(scene.camera.interocular);
  stereo.parameters.zero_parallax_distance =
      options.zero_parallax_distance.value_or(scene.camera.zero_parallax_distance);
  stereo.eye_order = options.swap_eyes.value_or(scene.camera.swap_eyes) ? EyeOrder::right_left
                                                                        : EyeOrder::left_right;
  world_.emplace<StereoCamera>(camera, stereo);
  if (scene.camera.orbit_deg_per_second != 0.0f)
    world_.emplace<CameraOrbit>(camera, CameraOrbit{scene.camera.position, scene.camera.orbit_deg_per_second});

  for (size_t k = 0; k < scene.clouds.size(); ++k) {
    const CloudDescription& d = scene.clouds[k];
    const ecs::Entity e = world_.create();
    CloudVolume c;
    c.box_min = d.box_min;
    c.box_max = d.box_max;
    c.count = d.count;
    c.radius = d.radius;
    c.density = d.density;
    c.color = d.color;
    c.seed = mix_seeds(scene.seed, d.seed * 1000003ull + k);
    c.drift = d.drift;
    c.jitter = d.jitter;
    world_.emplace<CloudVolume>(e, c);
    world_.emplace<ParticleSet>(e, ParticleSet{ParticlePool(d.count)});
  }
  // Volumes: particles read or imported now (errors name the scene, the entry and the file), then
  // fixed; the sorting and billboard systems draw them like any other ParticleSet.
  for (const VolumeDescription& v : scene.volumes) {
    if (v.used_fallback) {
      std::fprintf(stderr, "pyro: %s: %s: volume file \"%s\" not found; using the fallback \"%s\"\n",
                   scene.file.c_str(), v.pointer.c_str(), v.file.c_str(), v.path.c_str());
    } else {
      std::fprintf(stderr, "pyro: %s: %s: using volume file \"%s\"\n", scene.file.c_str(),
                   v.pointer.c_str(), v.path.c_str());
    }
    SceneVolume loaded = load_scene_volume(scene, v);
    if (!loaded.note.empty())
      std::fprintf(stderr, "pyro: %s: %s\n", v.path.c_str(), loaded.note.c_str());
    const ecs::Entity e = world_.create();
    world_.emplace<ParticleSet>(e, ParticleSet{to_particle_pool(loaded.particles)});
    world_.emplace<VolumeSource>(
        e, VolumeSource{v.path, v.used_fallback, loaded.active_voxels, loaded.particles.size()});
  }
  if (!scene.volumes.empty()) {
    uint64_t volume_particles = 0;
    world_.each<VolumeSource>([&](VolumeSource& source) { volume_particles += source.particles; });
    check_budget(volume_particles);
  }
  world_.set_resource<SimulationEnvironment>(scene.environment);
  for (size_t k = 0; k < scene.emitters.size(); ++k) {
    const EmitterDescription& d = scene.emitters[k];
    const ecs::Entity e = world_.create();
    Emitter em = d.emitter;
    // Its own stream: the scene seed mixed with the emitter's seed and its place in the file
    // (a different odd constant from the clouds', so an emitter and a cloud never share one).
    em.seed = mix_seeds(scene.seed, d.emitter.seed * 2654435761ull + k + 0x5EEDull);
    em.rng = Rng(em.seed);
    world_.emplace<Emitter>(e, std::move(em));
    world_.emplace<ParticleDynamics>(e, d.dynamics);
    world_.emplace<ParticleSet>(e, ParticleSet{ParticlePool(d.emitter.budget)});
  }
  for (const MeshDescription& m : scene.meshes) {
    world_.emplace<MeshInstance>(world_.create(), MeshInstance{m.kind, m.position, m.scale, m.color});
  }

  add_flipbook_fires(world_, scene.fires);  // reads (or first bakes) the flipbooks

  world_.set_resource<GpuFrame>(make_gpu_frame(settings));
  world_.set_resource<BillboardRenderer>(
      make_footprint_table(scene.footprint.size, scene.footprint.intervals));

  if (scene.prewarm > 0.0f)
    prewarm_particles(world_, static_cast<uint64_t>(std::llround(scene.prewarm / clock.dt)));

  std::vector<ecs::SystemDesc> systems = {
      cloud_emitter_system(), particle_emitter_system(), drift_system(), particle_animation_system(),
      camera_orbit_system(),
      depth_sort_system(),    camera_system(),          flipbook_orient_system(),
      mesh_render_system(),   flipbook_render_system(), billboard_render_system(), stereo_compose_system()};
  if (options.readback) systems.push_back(frame_readback_system());
  profiling_ = options.profile;
  if (profiling_) {
    profile_origin_ = std::chrono::steady_clock::now();
    gpu_timer_ = std::make_unique<gpu::GpuPassTimer>(profile_origin_);
  }
  for (ecs::SystemDesc& d : systems) {
    if (profiling_ && d.phase >= ecs::Phase::render) {
      // Systems that issue GL commands: their GPU time is a pass of its own on the GPU track.
      d.run = [run = std::move(d.run), name = d.name](ecs::World& w) {
        gpu::GpuPassScope pass(name.c_str());
        run(w);
      };
    }
    if (options.sync_timing) {
      d.run = [run = std::move(d.run)](ecs::World& w) {
        run(w);
        glFinish();
      };
    }
    schedule_.add(std::move(d));
  }
}

void SceneRuntime::step() {
  make_current_();
  if (!profiling_) {
    schedule_.run_frame(world_);
    world_.resource<FrameClock>().frame += 1;
    return;
  }
  // Last frame's GPU passes are read now, a frame late, so reading them rarely waits.
  collect_gpu_spans();
  gpu_timer_->begin_frame(frame());
  struct ActiveTimer {  // the render passes report to this runtime's timer while it runs
    explicit ActiveTimer(gpu::GpuPassTimer* t) { gpu::set_active_gpu_pass_timer(t); }
    ~ActiveTimer() { gpu::set_active_gpu_pass_timer(nullptr); }
  } active(gpu_timer_.get());
  schedule_.run_frame(world_);
  record_cpu_spans();
  world_.resource<FrameClock>().frame += 1;
}

void SceneRuntime::record_cpu_spans() {
  const auto us = [&](std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double, std::micro>(t - profile_origin_).count();
  };
  const auto& stats = schedule_.stats();
  if (stats.empty()) return;
  const uint64_t f = frame();
  const double frame_start = us(stats.front().last_start);
  double frame_end = frame_start;
  const size_t first = trace_.size();
  trace_.push_back({"frame " + std::to_string(f), "frame", TraceTrack::cpu, frame_start, 0.0, f, -1});
  for (const ecs::SystemStats& s : stats) {
    const double start = us(s.last_start);
    trace_.push_back({s.name, ecs::phase_name(s.phase), TraceTrack::cpu, start, s.last_ms * 1e3, f, -1});
    frame_end = std::max(frame_end, start + s.last_ms * 1e3);
  }
  trace_[first].duration_us = frame_end - frame_start;
}

void SceneRuntime::collect_gpu_spans() {
  for (gpu::GpuPassSample& s : gpu_timer_->collect())
    trace_.push_back({std::move(s.name), "gpu", TraceTrack::gpu, s.start_us, s.duration_us, s.frame,
                      s.fragments});
}

const std::vector<TraceSpan>& SceneRuntime::trace() {
  if (profiling_) {
    make_current_();
    glFinish();
    collect_gpu_spans();
  }
  return trace_;
}

void SceneRuntime::redraw() {
  make_current_();
  // The last frame drawn was the one before the clock's (step() advances it after drawing):
  // draw at that frame again, so time-dependent shading (heat shimmer) stays put.
  FrameClock& clock = world_.resource<FrameClock>();
  const uint64_t next = clock.frame;
  if (next > 0) clock.frame = next - 1;
  schedule_.run_phases(world_, ecs::Phase::sort, ecs::Phase::output);
  world_.resource<FrameClock>().frame = next;
}

void SceneRuntime::simulate_step() {
  schedule_.run_phases_through(world_, ecs::Phase::simulate);
  world_.resource<FrameClock>().frame += 1;
}

uint64_t SceneRuntime::frame() const {
  return const_cast<ecs::World&>(world_).resource<FrameClock>().frame;
}

const FrameImage& SceneRuntime::image() {
  const FrameImage* img = world_.try_resource<FrameImage>();
  if (!img || !img->valid) throw std::logic_error("no frame has been read back yet");
  return *img;
}

const RenderSettings& SceneRuntime::settings() { return world_.resource<RenderSettings>(); }

const gpu::RenderTarget& SceneRuntime::output_target() {
  const GpuFrame& frame = world_.resource<GpuFrame>();
  return frame.display ? *frame.display : *frame.output;
}

SceneRuntime::OutputImage SceneRuntime::read_output() {
  make_current_();
  const gpu::RenderTarget& out = output_target();
  return {out.width(), out.height(), out.read_rgba8()};
}

std::vector<std::string> SceneRuntime::write_png(const std::string& stem) {
  const OutputImage image = read_output();
  const std::vector<uint8_t>& rgba = image.rgba;
  const int w = image.width, h = image.height;
  // Drop alpha; in left-right mode the output holds both views side by side: split it.
  auto rgb_columns = [&](int x0, int width) {
    std::vector<uint8_t> rgb(static_cast<size_t>(width) * h * 3);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < width; ++x)
        for (int c = 0; c < 3; ++c)
          rgb[(static_cast<size_t>(y) * width + x) * 3 + c] =
              rgba[(static_cast<size_t>(y) * w + x0 + x) * 4 + c];
    return rgb;
  };
  std::vector<std::string> written;
  if (settings().stereo_mode == StereoMode::left_right) {
    const int half = w / 2;
    pyro::write_png(stem + "_left.png", half, h, 3, rgb_columns(0, half));
    written.push_back(stem + "_left.png");
    pyro::write_png(stem + "_right.png", half, h, 3, rgb_columns(half, half));
    written.push_back(stem + "_right.png");
  } else {
    pyro::write_png(stem + ".png", w, h, 3, rgb_columns(0, w));
    written.push_back(stem + ".png");
  }
  return written;
}

}  // namespace pyro
