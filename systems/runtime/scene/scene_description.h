#pragma once
// What a scene file says, as plain data: the loader (scene_loader.h) fills it from JSON and
// checks every value; the scene builder turns it into entities.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "components/ambient_light.h"
#include "components/directional_light.h"
#include "components/emitter.h"
#include "components/mesh_instance.h"
#include "components/render_modes.h"
#include "components/render_settings.h"
#include "components/flipbook_fire.h"
#include "components/light_keyframes.h"
#include "components/particle_dynamics.h"
#include "components/shadow_settings.h"
#include "components/simulation_environment.h"
#include "systems/runtime/scene/scene_budget.h"

namespace pyro {

struct CameraDescription {
  glm::vec3 position{0.0f, 1.5f, 8.0f};
  glm::vec3 target{0.0f, 1.5f, 0.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float fov_y_deg = 45.0f;  // vertical field of view, (0, 180)
  float near = 0.1f;        // > 0
  float far = 200.0f;       // > near
  // Optional scripted motion: the camera orbits `target` about the vertical axis.
  float orbit_deg_per_second = 0.0f;
  // Stereo pair (used when a stereo output mode is chosen): off-axis, parallel view axes.
  float interocular = 0.065f;          // world units between the eyes, >= 0
  float zero_parallax_distance = 8.0f; // view depth where both eyes' images coincide, > 0
  bool swap_eyes = false;              // "eye_order": "right-left" puts the right eye first
};

struct RenderDescription {
  BillboardAlignment billboards = BillboardAlignment::viewplane;
  ParticleShape particles = ParticleShape::gaussian;
  // Particles are drawn into a layer of this fraction of the frame's size, then upsampled and
  // composited over the opaque scene: 1, 0.5, 0.25 or 0.125.
  float layer_scale = 1.0f;
  ParticleShading shading = ParticleShading::color;
  // Where the Gaussian splats' draw order is made: "auto" (the faster, measured), "cpu", "gpu".
  SortDevice sort_device = SortDevice::automatic;
  // Motion blur by blending frames (Umenhoffer et al. 2006, section 4): each output frame is
  // (1 - b) times the new frame plus b times the previous output, in linear light; 0 is off.
  float motion_blur = 0.0f;
  // Fire under explosion shading (components/explosion_shading.h): the black-body table's
  // temperature range (T outside it clamps to its ends), the emission scale and the detail
  // noise's temperature range. Defaults are the paper's 2500-3200 K; flames whose tips cool to
  // 1000-1500 K need a wider table to turn red and dark.
  float fire_t_min = 2500.0f;
  float fire_t_max = 3200.0f;
  float fire_emission = 6.0f;
  float fire_detail_range = 500.0f;
};

// A cloud of identical Gaussian particles placed uniformly at random in a box
// (Johnson & McAllister 2005, section 4: r, rho and grey colour c per scene).
struct CloudDescription {
  std::string name;                          // optional, for reports
  uint32_t count = 1000;                     // 1 .. 10,000,000
  float radius = 0.4f;                       // world units, > 0
  float density = 0.4f;                      // opacity at the kernel centre, [0, 1]
  glm::vec3 color{0.8f, 0.8f, 0.8f};         // linear, each in [0, 1]; a number c means (c,c,c)
  glm::vec3 box_min{-4.0f, 0.0f, -4.0f};     // box_min < box_max on every axis
  glm::vec3 box_max{4.0f, 4.0f, 4.0f};
  uint64_t seed = 1;                         // mixed with the scene seed
  glm::vec3 drift{0.0f, 0.0f, 0.0f};         // common drift velocity, world units / s
  float jitter = 0.0f;                       // per-particle random speed, >= 0
  // What its particles are drawn as (components/particle_kind.h); absent: render.particles.
  std::optional<ParticleShape> particles;
};

// An opaque mesh (docs/scene_format.md, meshes[]): a built-in mesh, a primitive of given size
// or a mesh file, placed by MeshPlacement (engine/mesh/mesh_placement.h). Primitives stand on
// their origin: the box, cylinder and cone have their base centred on it and rise along +y; the
// sphere's centre is (0, radius, 0) in model space.
struct MeshDescription {
  MeshKind kind = MeshKind::ground_plane;
  glm::vec3 position{0.0f, 0.0f, 0.0f};
  glm::vec3 rotation_deg{0.0f, 0.0f, 0.0f};  // Euler angles: about x, then y, then z
  float scale = 1.0f;                        // > 0; for the ground plane: half the side length
  glm::vec3 color{0.5f, 0.5f, 0.5f};         // linear albedo, each in [0, 1]
  glm::vec3 size{1.0f, 1.0f, 1.0f};          // box: full extents, each > 0
  float radius = 0.5f;                       // sphere, cylinder, cone: > 0
  float height = 1.0f;                       // cylinder, cone: > 0
  std::string file;                          // file: as written in the scene
  std::string path;                          // file: resolved against the scene file's folder
  std::string pointer;                       // JSON pointer of the entry, e.g. "/meshes/0"
};

// A volume read from a file: an OpenVDB grid imported as Gaussian particles when the scene is
// loaded (systems/runtime/cloud_import), or a particle file (.pyrop, docs/particle_format.md) made by
// `pyro import-vdb`. Paths are resolved against the scene file's folder by the loader, which also
// chooses between `file` and `fallback` (the first that exists).
// A particle sequence (a `.pyroseq` folder, engine/io/particle_sequence.h) is an animated volume:
// `sequence` says how it plays.
enum class VolumeFileKind { vdb, particles, sequence };

// How a particle sequence plays (docs/scene_format.md, volumes[]): source frame position
// s(t) = start + t * fps * speed at scene time t, the two frames around s cross-faded.
struct SequencePlayback {
  bool has_start_frame = false;
  int64_t start_frame = 0;  // a source frame number of the sequence (checked against its manifest)
  bool loop = false;        // wrap after the last frame (else hold it)
  float speed = 1.0f;       // (0, 1000]: times the sequence's own fps
};

// A volume's fire (docs/scene_format.md, volumes[].emission): how its temperature values become
// kelvin and how bright the hottest glows (engine/math/temperature_emission.h).
struct VolumeEmissionDescription {
  bool automatic = true;  // no "temperature" map given: the file's recorded map, else the automatic one
  float scale = 1.0f, offset = 0.0f;  // kelvin = scale * value + offset
  std::vector<std::array<float, 2>> table;  // (value, kelvin), values ascending; used when not empty
  // The largest component of the hottest temperature's emitted radiance (engine/math/
  // temperature_emission.h). Not given: the volume's exposure (systems/runtime/cloud_import/
  // fire_exposure.h), which a particle file records from its import.
  bool intensity_given = false;
  float intensity = 4.0f;
};

struct VolumeDescription {
  std::string name;                          // optional, for reports
  std::string file;                          // as written in the scene
  std::string fallback;                      // as written; empty: none
  std::string path;                          // resolved: the file that will be read
  VolumeFileKind kind = VolumeFileKind::vdb; // of `path`, from its extension
  bool used_fallback = false;                // `file` was absent and `fallback` was found
  std::string pointer;                       // JSON pointer of the entry, e.g. "/volumes/0"
  // VDB only: which grid (as `pyro import-vdb --grid / --grid-index`), the image error target
  // that sets the particle count, and the extinction per unit density (0: automatic, see
  // default_extinction in systems/runtime/cloud_import/cloud_import.h).
  std::string grid;                          // empty: "density", else the first float grid
  int grid_index = -1;                       // >= 0: overrides `grid`
  float error = 0.03f;                       // (0, 1]
  float extinction = 0.0f;                   // >= 0, world units^-1 per unit density
  std::string temperature_grid;              // VDB only: empty: automatic; "none": off
  VolumeEmissionDescription emission;
  // Placement: p_scene = position + scale * (p_file - anchor), where anchor is the centre of the
  // particles' bounding box (anchor "center") or the file's origin (anchor "origin"). `size`,
  // when given, sets scale so that the bounding box's longest side is `size` world units. Radii
  // scale too; opacities do not (a change of units: the volume looks the same at any size).
  bool anchor_center = true;
  glm::vec3 position{0.0f, 0.0f, 0.0f};
  float scale = 1.0f;                        // > 0
  float size = 0.0f;                         // > 0 when given; excludes `scale`
  SequencePlayback sequence;                 // kind == sequence only
};

struct FootprintDescription {
  int size = 64;        // table is size x size, 2 .. 4096 (Johnson & McAllister eq. 4)
  int intervals = 100;  // composite quadrature intervals along z, 1 .. 100000
};

// "quality": {"max_rmse": E}: instead of explicit settings, the engine picks the layer scale,
// footprint table size and time step that keep the image's RMSE against the ground truth at
// most E at the least measured cost (systems/runtime/quality).
struct QualityDescription {
  float max_rmse = 0.0f;  // (0, 1]; 0: no target given (the scene's own settings are used)
  bool given() const { return max_rmse > 0.0f; }
};

// An explosion emitter: what it spawns (components/emitter.h; its state fields stay at
// their defaults) and how its particles move (components/particle_dynamics.h). The plain-data
// components double as the description, so scene keys and component fields cannot drift apart.
struct EmitterDescription {
  Emitter emitter;            // emitter.seed is the file's seed, not yet mixed
  ParticleDynamics dynamics;
  // What its particles are drawn as (components/particle_kind.h); absent: render.particles.
  std::optional<ParticleShape> particles;
};

struct SceneDescription {
  std::string file;                          // where it was read from
  std::string content_digest;                // SHA-256 of the parsed JSON (canonical form)
  std::string name;
  uint64_t seed = 1;
  int width = 800;                           // 1 .. 8192
  int height = 600;                          // 1 .. 8192
  float frames_per_second = 30.0f;           // > 0
  OutputBackground output_background = OutputBackground::opaque;  // output.background
  glm::vec3 background{0.62f, 0.68f, 0.76f}; // linear RGB sky colour
  CameraDescription camera;
  // The scene's lights (the components double as descriptions): `light` gives one directional
  // and one ambient light, `lights` any number of each; without either key, the defaults.
  std::vector<DirectionalLight> directional_lights = std::vector<DirectionalLight>(1);
  // Beside each directional light, its keyframes (empty: it does not move).
  std::vector<LightKeyframes> light_keyframes = std::vector<LightKeyframes>(1);
  std::vector<AmbientLight> ambient_lights = std::vector<AmbientLight>(1);
  // Lit media (docs/lighting.md): absent, the splats keep their colours as given, unlit.
  std::optional<ShadowSettings> shadows;
  FootprintDescription footprint;
  RenderDescription render;
  std::vector<CloudDescription> clouds;
  std::vector<MeshDescription> meshes;
  std::vector<VolumeDescription> volumes;
  // Shared by every emitter: gravity, wind, ambient temperature, colliders, scene budget.
  SimulationEnvironment environment;
  float prewarm = 0.0f;                      // seconds run before frame 0, >= 0
  std::vector<EmitterDescription> emitters;
  // Flipbook fires (Rose 2007, chapter 4): the component doubles as the description; its
  // `flipbook` is resolved against the scene's folder (empty: the engine's baked flipbook).
  std::vector<FlipbookFire> fires;
  SceneBudget budget;                        // refused up front when exceeded (scene_budget.h)
  QualityDescription quality;                // optional error target
};

}  // namespace pyro
