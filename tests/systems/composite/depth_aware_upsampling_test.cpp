// Depth-aware upsampling of the explosion media layers (content/shaders/compose.frag,
// upsampled_media) against plain bilinear upsampling, each against the same frames rendered
// with full-resolution layers:
// - where the depth is continuous everywhere (particles over a tilted plane that fills the view)
//   the two images agree to 1e-4: depth-aware upsampling is bilinear there;
// - on the paper's explosion, as `pyro chart layer-resolution` renders it, its whole-image RMSE is
//   at most bilinear's + 1e-4 at every scale;
// - behind an opaque edge (a dust particle under the edge of a plane) its error near the edge and
//   its halo (engine/math/depth_edge_error.h) are lower than bilinear's at 1/2, 1/4 and 1/8;
// - a surface nearer than every particle (a water tower in front of dust), however thin, shows
//   the scene alone, as with full-resolution layers, where bilinear upsampling carries the dust
//   onto its legs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "components/draw_list.h"
#include "components/frame_image.h"
#include "components/gpu_frame.h"
#include "components/view.h"
#include "engine/math/depth_edge_error.h"
#include "engine/math/image_error.h"
#include "systems/composite/compositor.h"
#include "systems/composite/opaque_view_readback.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"

namespace pyro {
namespace {

constexpr float scales[] = {0.5f, 0.25f, 0.125f};

// Dust (cloud particles are medium 0) in explosion shading, over opaque geometry.
SceneDescription dust_over(const MeshDescription& mesh, int size) {
  SceneDescription s;
  s.width = s.height = size;
  s.background = {0.1f, 0.1f, 0.1f};
  s.camera.fov_y_deg = 50.0f;
  s.directional_lights.at(0).direction = {-0.3f, -1.0f, -0.2f};
  s.directional_lights.at(0).color = {1.0f, 1.0f, 1.0f};
  s.ambient_lights.at(0).color = {0.1f, 0.1f, 0.1f};
  s.render.particles = ParticleShape::spherical;
  s.render.shading = ParticleShading::explosion;
  s.meshes.push_back(mesh);
  return s;
}

// Looking down at a ground plane that fills the view (its far end is out of sight), with dust
// drifting over it and into it: the particles' clipping changes, the depth never jumps.
SceneDescription tilted_plane() {
  MeshDescription ground;
  ground.kind = MeshKind::ground_plane;
  ground.scale = 60.0f;
  ground.color = {0.3f, 0.35f, 0.5f};
  SceneDescription s = dust_over(ground, 128);
  s.camera.position = {0.0f, 2.0f, 0.0f};
  s.camera.target = {0.0f, 0.0f, -3.0f};  // 34 degrees down: the view's top edge 9 degrees down
  CloudDescription c;
  c.count = 24;
  c.radius = 0.7f;
  c.density = 2.0f;
  c.box_min = {-2.0f, -0.3f, -6.0f};
  c.box_max = {2.0f, 1.0f, -2.5f};
  s.clouds.push_back(c);
  return s;
}

// Looking down at a plane whose edge crosses the view, a bright dust particle below it, half
// under the plane, half beyond its edge. The view is turned a little about its axis, so that the
// edge crosses the layer's texels at every offset.
SceneDescription dust_below_an_edge() {
  MeshDescription plane;
  plane.kind = MeshKind::ground_plane;
  plane.scale = 2.0f;  // the plane spans x, z in [-2, 2]
  plane.color = {0.0f, 0.0f, 1.0f};
  SceneDescription s = dust_over(plane, 128);
  s.background = {0.0f, 0.0f, 0.0f};
  s.camera.position = {0.0f, 6.0f, 0.0f};
  s.camera.target = {0.0f, 0.0f, 0.0f};
  s.camera.up = {0.3f, 0.0f, -1.0f};
  s.directional_lights.at(0).direction = {0.0f, -1.0f, 0.0f};
  CloudDescription c;
  c.count = 1;
  c.radius = 1.6f;
  c.density = 3.0f;
  c.box_min = c.box_max = {2.4f, -2.0f, 0.0f};
  s.clouds.push_back(c);
  return s;
}

// A water tower in front of a bright dust particle, nothing else (the background is far): at 1/4
// and 1/8 of 128 pixels the tower's legs are thinner than a layer texel.
SceneDescription dust_behind_a_tower() {
  MeshDescription tower;
  tower.kind = MeshKind::water_tower;
  tower.position = {0.0f, 0.0f, 3.0f};
  tower.color = {0.5f, 0.5f, 0.5f};
  SceneDescription s = dust_over(tower, 128);
  s.camera.position = {0.0f, 4.0f, 14.0f};
  s.camera.target = {0.0f, 4.0f, 0.0f};
  CloudDescription c;
  c.count = 1;
  c.radius = 4.0f;
  c.density = 3.0f;
  c.box_min = c.box_max = {0.5f, 4.5f, -6.0f};
  s.clouds.push_back(c);
  return s;
}

struct Errors {
  double rmse = 0.0;
  DepthEdgeError edges;
};

// Frames `every`, 2 every, ... up to `frames` of the scene at `scale` with each upsampling, against
// full-resolution layers: RMSE and edge RMSE as root mean squares over the frames, the largest
// halo. [0]: depth-aware, [1]: bilinear.
std::array<Errors, 2> measure(const SceneDescription& scene, int size, float scale, int frames,
                              int every) {
  RuntimeOptions full;
  full.width_override = full.height_override = size;
  full.layer_scale = 1.0f;
  RuntimeOptions reduced = full;
  reduced.layer_scale = scale;
  SceneRuntime reference(scene, full), depth_aware(scene, reduced), bilinear(scene, reduced);
  MediaComposition plain;
  plain.depth_aware = false;
  bilinear.world().set_resource<MediaComposition>(plain);
  std::array<Errors, 2> sums{};
  int samples = 0;
  for (int f = 1; f <= frames; ++f) {
    reference.step();
    depth_aware.step();
    bilinear.step();
    if (f % every != 0) continue;
    ecs::World& world = reference.world();
    const OpaqueView opaque = read_opaque_view(world.resource<GpuFrame>(), world.resource<View>(),
                                               world.resource<EyeDrawLists>());
    const std::vector<float>& truth = reference.image().rgba;
    SceneRuntime* runs[2] = {&depth_aware, &bilinear};
    for (size_t k = 0; k < 2; ++k) {
      const std::vector<float>& image = runs[k]->image().rgba;
      const double e = rgba_rmse(image, truth);
      const DepthEdgeError d = depth_edge_error({opaque.width, opaque.height, opaque.view_depth,
                                                 opaque.rgba, truth, image, opaque.particle_far});
      sums[k].rmse += e * e;
      sums[k].edges.edge_rmse += d.edge_rmse * d.edge_rmse;
      sums[k].edges.edge_pixels = d.edge_pixels;
      sums[k].edges.halo = std::max(sums[k].edges.halo, d.halo);
      sums[k].edges.halo_pixels += d.halo_pixels;
    }
    ++samples;
  }
  for (Errors& e : sums) {
    e.rmse = std::sqrt(e.rmse / samples);
    e.edges.edge_rmse = std::sqrt(e.edges.edge_rmse / samples);
  }
  return sums;
}

TEST(DepthAwareUpsampling, IsBilinearWhereTheDepthIsContinuous) {
  const SceneDescription scene = tilted_plane();
  for (float scale : scales) {
    RuntimeOptions o;
    o.layer_scale = scale;
    SceneRuntime depth_aware(scene, o), bilinear(scene, o);
    MediaComposition plain;
    plain.depth_aware = false;
    bilinear.world().set_resource<MediaComposition>(plain);
    depth_aware.step();
    bilinear.step();
    const std::vector<float>& a = depth_aware.image().rgba;
    const std::vector<float>& b = bilinear.image().rgba;
    ASSERT_EQ(a.size(), b.size());
    float largest = 0.0f, media = 0.0f;
    for (size_t i = 0; i < a.size(); ++i) {
      if (i % 4 == 3) continue;
      largest = std::max(largest, std::abs(a[i] - b[i]));
      media = std::max(media, a[i]);
    }
    EXPECT_LE(largest, 1e-4f) << scale;
    // The dust is there to be upsampled (the plane alone is darker than 0.5).
    EXPECT_GT(media, 0.5f) << scale;
  }
}

TEST(DepthAwareUpsampling, NeverWorseThanBilinearOnTheExplosion) {
  // As the chart measures it: 256 x 256, frames 4, 8, 12, 16.
  const SceneDescription scene =
      load_scene(std::string(PYRO_SOURCE_DIR) + "/content/scenes/explosion.json");
  for (float scale : scales) {
    const std::array<Errors, 2> e = measure(scene, 256, scale, 16, 4);
    EXPECT_LE(e[0].rmse, e[1].rmse + 1e-4) << scale;
    EXPECT_GT(e[1].rmse, 0.0) << scale;
  }
}

TEST(DepthAwareUpsampling, LessErrorAndHaloThanBilinearBehindAnEdge) {
  const SceneDescription scene = dust_below_an_edge();
  for (float scale : scales) {
    const std::array<Errors, 2> e = measure(scene, 128, scale, 1, 1);
    ASSERT_GT(e[1].edges.edge_pixels, 0u) << scale;
    ASSERT_GT(e[1].edges.halo_pixels, 0u) << scale;
    EXPECT_LT(e[0].edges.edge_rmse, e[1].edges.edge_rmse) << scale;
    EXPECT_LT(e[0].rmse, e[1].rmse) << scale;
    // Bilinear filtering at 1/2 reaches 2 pixels: no halo beyond them with either.
    if (scale < 0.5f)
      EXPECT_LT(e[0].edges.halo, e[1].edges.halo) << scale;
    else
      EXPECT_LE(e[0].edges.halo, e[1].edges.halo) << scale;
    EXPECT_LE(e[0].edges.halo, 1e-3) << scale;
  }
}

TEST(DepthAwareUpsampling, ASurfaceInFrontOfEveryParticleShowsTheSceneAlone) {
  const SceneDescription scene = dust_behind_a_tower();
  // The tower's pixels: nearer than the dust's front (view depth 20 - 4 = 16), by a margin.
  const float tower_depth = 14.0f;
  for (float scale : scales) {
    RuntimeOptions full;
    full.layer_scale = 1.0f;
    RuntimeOptions reduced;
    reduced.layer_scale = scale;
    SceneRuntime reference(scene, full), depth_aware(scene, reduced), bilinear(scene, reduced);
    MediaComposition plain;
    plain.depth_aware = false;
    bilinear.world().set_resource<MediaComposition>(plain);
    reference.step();
    depth_aware.step();
    bilinear.step();
    ecs::World& world = reference.world();
    const OpaqueView opaque = read_opaque_view(world.resource<GpuFrame>(), world.resource<View>(),
                                               world.resource<EyeDrawLists>());
    const std::vector<float>& truth = reference.image().rgba;
    const std::vector<float>& a = depth_aware.image().rgba;
    const std::vector<float>& b = bilinear.image().rgba;
    float depth_aware_light = 0.0f, bilinear_light = 0.0f, dust = 0.0f;
    size_t tower_pixels = 0;
    for (size_t p = 0; p < opaque.view_depth.size(); ++p) {
      const bool tower = opaque.view_depth[p] < tower_depth;
      tower_pixels += tower;
      for (size_t c = 0; c < 3; ++c) {
        const size_t i = 4 * p + c;
        if (tower) {
          depth_aware_light = std::max(depth_aware_light, std::abs(a[i] - truth[i]));
          bilinear_light = std::max(bilinear_light, std::abs(b[i] - truth[i]));
        } else {
          dust = std::max(dust, truth[i] - opaque.rgba[i]);
        }
      }
    }
    ASSERT_GT(tower_pixels, 200u) << scale;
    EXPECT_GT(dust, 0.1f) << scale << ": the dust shows around the tower";
    // No particle lies in front of the tower: its pixels show the scene alone, as at full size.
    EXPECT_LE(depth_aware_light, 1e-4f) << scale << " (bilinear: " << bilinear_light << ")";
    if (scale < 0.5f) {
      EXPECT_GT(bilinear_light, 0.02f) << scale;
    }
  }
}

}  // namespace
}  // namespace pyro
