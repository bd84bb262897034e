#pragma once
// What a scene file says, as plain data: the loader (scene_loader.h) fills it from JSON and
// checks every value; the scene builder turns it into entities.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "components/emitter.h"
#include "components/particle_dynamics.h"
#include "components/simulation_environment.h"

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
};

// How particle billboards are oriented (Johnson & McAllister 2005, section 3): all facing the
// viewplane (one rotation per eye) or each facing the viewpoint (one rotation per particle).
enum class BillboardAlignment { viewplane, viewpoint };

struct RenderDescription {
  BillboardAlignment billboards = BillboardAlignment::viewplane;
  // Particles are drawn into a layer of this fraction of the frame's size, then upsampled and
  // composited over the opaque scene: 1, 0.5, 0.25 or 0.125.
  float layer_scale = 1.0f;
};

struct LightDescription {
  glm::vec3 direction{-0.4f, -1.0f, -0.3f};  // direction the light travels; non-zero
  glm::vec3 color{1.0f, 1.0f, 1.0f};         // linear RGB, each >= 0
  glm::vec3 ambient{0.35f, 0.38f, 0.45f};    // linear RGB, each >= 0
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
};

enum class MeshKind { ground_plane, water_tower };

struct MeshDescription {
  MeshKind kind = MeshKind::ground_plane;
  glm::vec3 position{0.0f, 0.0f, 0.0f};
  float scale = 1.0f;                        // > 0; for the ground plane: half the side length
  glm::vec3 color{0.5f, 0.5f, 0.5f};         // linear albedo, each in [0, 1]
};

struct FootprintDescription {
  int size = 64;        // table is size x size, 2 .. 4096 (Johnson & McAllister eq. 4)
  int intervals = 100;  // composite quadrature intervals along z, 1 .. 100000
};

// An explosion emitter (issue 4): what it spawns (components/emitter.h; its state fields stay at
// their defaults) and how its particles move (components/particle_dynamics.h). The plain-data
// components double as the description, so scene keys and component fields cannot drift apart.
struct EmitterDescription {
  Emitter emitter;            // emitter.seed is the file's seed, not yet mixed
  ParticleDynamics dynamics;
};

struct SceneDescription {
  std::string file;                          // where it was read from
  std::string name;
  uint64_t seed = 1;
  int width = 800;                           // 1 .. 8192
  int height = 600;                          // 1 .. 8192
  float frames_per_second = 30.0f;           // > 0
  glm::vec3 background{0.62f, 0.68f, 0.76f}; // linear RGB sky colour
  CameraDescription camera;
  LightDescription light;
  FootprintDescription footprint;
  RenderDescription render;
  std::vector<CloudDescription> clouds;
  std::vector<MeshDescription> meshes;
  // Shared by every emitter: gravity, wind, ambient temperature, colliders, scene budget.
  SimulationEnvironment environment;
  float prewarm = 0.0f;                      // seconds run before frame 0, >= 0
  std::vector<EmitterDescription> emitters;
};

}  // namespace pyro
