#pragma once
// Imported particles in a scene of their own, for the benchmarks that relight a volume: the
// grid's framing camera, the medium's sun, ambient light and background, and `shadows` (none:
// unlit, the particles' colours as they are).
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "components/shadow_settings.h"
#include "components/volume_medium.h"
#include "engine/io/vdb_reader.h"
#include "engine/particles/anisotropic_gaussian.h"
#include "engine/particles/gaussian_particle.h"
#include "systems/runtime/scene/scene_description.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"

namespace pyro {

struct RelitView {
  CameraDescription camera;
  int width = 512, height = 512;
  bool readback = true;  // keep each frame's image (scoring) or not (timing)
};

SceneRuntime relit_particles_runtime(const std::vector<GaussianParticle>& particles, const VolumeMedium& medium,
                                     const RelitView& view, const std::optional<ShadowSettings>& shadows);
// The same for fitted anisotropic particles (an AnisotropicCloud; unlit, drawn in their colours).
SceneRuntime relit_particles_runtime(const std::vector<AnisotropicGaussian>& particles, const VolumeMedium& medium,
                                     const RelitView& view, const std::optional<ShadowSettings>& shadows);

// The grid imported as a lit scene imports its volumes (systems/runtime/cloud_import/scene_volume.cpp):
// the particles keep their albedo (no sun, ambient 1), to within the import's `error` target.
std::vector<GaussianParticle> import_keeping_albedo(const DenseGrid& grid, double extinction, double albedo,
                                                    double error);

// Points the runtime's sun along `direction` (the direction the light travels).
void set_sun(SceneRuntime& runtime, const glm::dvec3& direction);

}  // namespace pyro
