#pragma once
// How a scene is run: what replaces the scene's own choices (size, stereo mode, billboards,
// particles, layer scale, shading, eyes, a quality pick) and what the runtime does besides
// drawing (readback, profiling, GPU sync after each system). Every layer of the runtime reads
// the part it needs: resolve_scene the replacements, standard_schedule the rest.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "components/render_modes.h"
#include "components/render_settings.h"
#include "components/shadow_settings.h"
#include "engine/ecs/schedule.h"
#include "systems/runtime/quality/quality_settings.h"

namespace pyro {

class SceneAssetCache;

// Receives the runtime's notes (which volume file was read, a flipbook being baked): one line
// each, without a program prefix. The library prints nothing itself.
using NoteSink = std::function<void(const std::string&)>;

struct RuntimeOptions {
  bool readback = true;     // read each frame's first view back into the FrameImage resource
  int width_override = 0;   // > 0: replaces the scene's output size (per eye)
  int height_override = 0;
  StereoMode stereo_mode = StereoMode::mono;
  std::optional<BillboardAlignment> alignment;  // replaces the scene's choice
  std::optional<ParticleShape> particles;       // replaces the scene's choice
  std::optional<float> layer_scale;             // replaces the scene's choice (and a quality pick's)
  std::optional<ParticleShading> shading;       // replaces the scene's choice
  std::optional<SortDevice> sort_device;        // replaces the scene's choice
  // Lit media (docs/lighting.md): `shadows_off` renders the scene unlit as if it had no
  // "shadows" block; else `shadow_method` replaces its method (lighting a scene without one).
  bool shadows_off = false;
  std::optional<ShadowMethod> shadow_method;
  float frame_scale = 1.0f;                     // views at this fraction, output upscaled
  std::optional<OutputBackground> background;   // replaces the scene's output.background
  std::optional<float> interocular;
  std::optional<float> zero_parallax_distance;
  std::optional<bool> swap_eyes;  // replaces the scene's eye order
  // A quality pick (systems/runtime/quality_picker): its layer scale, footprint size and substeps are
  // applied to the scene before the options above.
  std::optional<QualitySettings> quality;
  // Finish the GPU's work after every system, so each system's timing includes the GPU work it
  // issued (profiling; it removes CPU/GPU overlap, so frames get slower).
  bool sync_timing = false;
  // Threads of the schedule (ecs::Schedule::set_threads): 0 one per core, 1 the sequential
  // schedule, n at most n. Results are the same for every count.
  int threads = 0;
  // Profiling: every step() records one span per system (CPU time, from the schedule)
  // and one per GPU pass (timer queries: each render, composite and output system, and the
  // layers inside billboard_render with the fragments they drew), read one frame late.
  bool profile = false;
  // Makes the OpenGL context the runtime renders with current. Empty: the shared headless EGL
  // context. The viewer (pyro view) passes its window's context, so that the output target
  // lives where the window can blit it.
  std::function<void()> make_context_current;
  // Where notes go while the assets load (empty: they are only kept, SceneRuntime::notes()).
  NoteSink on_note;
  // Volumes and prepared flipbooks kept from the last runtime built with the same cache, reused
  // when their inputs are unchanged (scene_asset_cache.h: the viewer rebuilding after an edit).
  // None: every file is read. Not owned; it must outlive the runtime's construction.
  SceneAssetCache* asset_cache = nullptr;
  // Systems of the embedding program's own (docs/embedding.md), added to the standard schedule
  // after its systems, each in its phase, with the same profiling wrappers.
  std::vector<ecs::SystemDesc> extra_systems;
};

}  // namespace pyro
