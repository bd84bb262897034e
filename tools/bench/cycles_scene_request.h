#pragma once
// A drawn frame of a running scene as Blender's Cycles sees it (content/cycles/render_scene.py,
// whose header holds the conventions): the camera of the first view, every sun and the ambient
// term of the light phase's block (components/light_block.h), every mesh in world space with its
// albedo, and the media voxelised as `pyro export-vdb` does (tools/export/media_voxels.h), with
// the albedo each renderer scatters with: a splat's colour, or an explosion medium's albedo
// (components/explosion_shading.h) under explosion shading.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/ecs/world.h"
#include "engine/math/camera_math.h"
#include "tools/bench/frame_regions.h"
#include "tools/export/media_voxels.h"

namespace pyro {

struct CyclesScene {
  CameraFrame camera;
  nlohmann::json request;                // render_scene.py's request, without "out", "samples", "seed"
  std::vector<WorldTriangle> triangles;  // every mesh, in world space
  MediaVoxels media;                     // empty box: none
  glm::dvec3 toward_key{0.0};            // unit; zero without a sun
  double voxel_error = 0.0;              // the media grid's column opacity error (column_error.h)
  int particles = 0;                     // media samples voxelised
  std::vector<std::string> approximations;  // what Cycles is given that the engine does differently
};

struct CyclesSceneOptions {
  double voxel_error = 0.01;        // column opacity error target of the media's grid
  uint64_t max_voxels = uint64_t{1} << 26;
  std::string vdb;                  // where the media's grid is written
};

// The world as drawn last (its View, LightBlock, MeshInstances and media). Writes options.vdb when
// the frame holds media. Throws UserError when the media need a grid over max_voxels.
CyclesScene cycles_scene_of(ecs::World& world, const CyclesSceneOptions& options);

}  // namespace pyro
