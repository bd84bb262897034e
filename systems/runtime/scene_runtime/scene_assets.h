#pragma once
// What a scene needs from files, read before its world is built: the mesh files' triangles, the volumes' particles
// (particle files read, isotropic or anisotropic; VDB grids imported) and the flipbooks' frames (read from their folders,
// prepared; the engine's default flipbook baked first when missing). Plain data:
// load_scene_assets.h makes it, build_world.h consumes it.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "components/volume_sequence.h"
#include "components/volume_source.h"
#include "engine/mesh/shared_mesh.h"
#include "engine/particles/anisotropic_gaussian.h"
#include "engine/particles/particle_pool.h"
#include "systems/flipbook_fire/flipbook_world.h"

namespace pyro {

struct VolumeAsset {
  ParticlePool particles;  // exactly sized, fixed after loading
  std::vector<AnisotropicGaussian> anisotropic;  // a version 2 particle file's particles
  VolumeSource source;
  // A particle sequence: its playback, which fills `particles` (empty, sized for the largest
  // drawn frame) every drawn frame (systems/volume_sequence).
  std::optional<VolumeSequence> sequence = std::nullopt;
};

struct SceneAssets {
  std::vector<VolumeAsset> volumes;  // one per scene.volumes entry, in order
  // One per scene.meshes entry, in order: the file's triangles for a "file" mesh, else null (the
  // world builds the primitives, systems/runtime/scene_runtime/mesh_geometry.h).
  std::vector<std::shared_ptr<const SharedMesh>> meshes;
  // scene.fires with their folders resolved (the default flipbook's where they named none),
  // and the prepared frames they use.
  std::vector<FlipbookFire> fires;
  FlipbookAssets flipbooks;
  std::vector<std::string> notes;  // every note reported while loading, in order
};

}  // namespace pyro
