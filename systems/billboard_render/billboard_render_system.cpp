#include "systems/billboard_render/billboard_render_system.h"

#include <vector>

#include "components/anisotropic_cloud.h"
#include "components/particle_kind.h"
#include "components/particle_set.h"
#include "components/particle_light.h"
#include "components/draw_list.h"
#include "components/explosion_shading.h"
#include "components/frame_clock.h"
#include "components/gpu_frame.h"
#include "components/render_settings.h"
#include "components/sort_device_choice.h"
#include "components/view.h"
#include "components/fire_lights.h"
#include "components/mesh_shadow.h"
#include "components/shadow_settings.h"
#include <glm/geometric.hpp>
#include <optional>
#include "engine/ecs/world.h"
#include "engine/gpu/gpu_pass_timer.h"
#include "systems/billboard_render/billboard_renderer.h"
#include "systems/billboard_render/explosion_renderer.h"
#include "systems/billboard_render/sphere_billboard_renderer.h"
#include "systems/lighting/light_buffer.h"
#include "systems/sorting/depth_sort.h"
#include "systems/sorting/particle_shapes.h"

#include <algorithm>

namespace pyro {

void draw_particles_for_view(BillboardRenderer& renderer, const EyeDrawLists& lists, size_t eye,
                             const CameraFrame& frame, EyeTargets& targets,
                             BillboardAlignment alignment, BillboardShading shading,
                             const SplatLighting* lighting) {
  const gpu::GpuPassScope pass("particle layer", true);  // profiling hook (no-op by default)
  const DrawList& list = lists.eyes[eye];
  if (!targets.layer) {
    renderer.draw(list, lists.pools, frame, *targets.scene, alignment, shading, lighting);
    return;
  }
  prepare_layer(targets);
  renderer.draw(list, lists.pools, frame, *targets.layer, alignment, shading, lighting);
}

void prepare_layer(EyeTargets& targets) {
  // Reduced resolution (Umenhoffer et al. 2006, section 4): the layer starts transparent, with
  // the scene's depth point-sampled down so opaque geometry still hides particles.
  const gpu::RenderTarget& scene = *targets.scene;
  const gpu::RenderTarget& layer = *targets.layer;
  glBlitNamedFramebuffer(scene.framebuffer(), layer.framebuffer(), 0, 0, scene.width(),
                         scene.height(), 0, 0, layer.width(), layer.height(),
                         GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  const float clear[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  glClearNamedFramebufferfv(layer.framebuffer(), GL_COLOR, 0, clear);
}

namespace {

// The renderer the scene's particle shape needs: the Gaussian BillboardRenderer is made from the
// scene's footprint table when the world is built; the others are made here, at setup.
void make_anisotropic_pass(ecs::World& world) {
  std::vector<AnisotropicGaussian> all;
  world.each<const AnisotropicCloud>([&](const AnisotropicCloud& c) {
    all.insert(all.end(), c.particles.begin(), c.particles.end());
  });
  if (all.empty()) return;
  world.set_resource<AnisotropicSplatPass>().renderer.upload(all);
}

void make_particle_renderer(ecs::World& world) {
  make_anisotropic_pass(world);
  const RenderSettings& settings = world.resource<const RenderSettings>();
  if (!world.has_resource<SortDeviceChoice>()) world.set_resource<SortDeviceChoice>();
  // Sets of other kinds than Gaussian (components/particle_kind.h) need a billboard renderer too.
  if (common_particle_shape(world, settings.particles) == ParticleShape::gaussian) return;
  if (settings.media_layers()) {
    const ExplosionShading* shading = world.try_resource<const ExplosionShading>();
    if (!world.has_resource<ExplosionRenderer>())
      world.set_resource<ExplosionRenderer>(shading ? *shading : ExplosionShading{});
    return;
  }
  if (!world.has_resource<SphereBillboardRenderer>()) world.set_resource<SphereBillboardRenderer>();
}

// Explosions (Umenhoffer et al. 2006, sections 3-4): each medium into its layer. The renderer
// bakes the shading's tables; a changed ExplosionShading resource takes a new one.
void draw_media(ecs::World& world, const EyeDrawLists& lists, const View& view, GpuFrame& frame,
                const RenderSettings& settings, size_t views) {
  const ExplosionShading* current = world.try_resource<const ExplosionShading>();
  const ExplosionShading shading = current ? *current : ExplosionShading{};
  ExplosionRenderer* explosion = &world.resource<ExplosionRenderer>();
  if (!(explosion->shading() == shading))
    explosion = &world.set_resource<ExplosionRenderer>(shading);
  const FrameClock* clock = world.try_resource<const FrameClock>();
  const double time = clock ? clock->time() : 0.0;
  // Lit media (a ShadowSettings resource): shadowed by the light phase's others' depth, or
  // exactly per fragment.
  const ShadowSettings* shadows = world.try_resource<const ShadowSettings>();
  const MediaLighting media_lighting = !shadows ? MediaLighting::unlit
                                       : shadows->exact_fragments ? MediaLighting::exact
                                                                  : MediaLighting::light_phase;
  const LightBuffer& lights = world.resource<const LightBuffer>();
  for (size_t v = 0; v < views; ++v)
    explosion->draw(lists.eyes[v], view.eyes[v], settings, lights, time, *frame.eyes[v].media_atlas,
                    frame.eyes[v].media_combined->width(), *frame.eyes[v].scene, media_lighting,
                    world.try_resource<const FireLights>(), world.try_resource<const MeshShadow>());
}

// Lit media (a ShadowSettings resource): the anisotropic clouds' light, their ParticleLights
// in the order make_anisotropic_pass uploaded the particles.
std::optional<AnisotropicLighting> anisotropic_lighting(ecs::World& world) {
  const ShadowSettings* shadows = world.try_resource<const ShadowSettings>();
  if (!shadows) return std::nullopt;
  AnisotropicLighting a;
  a.scene = &world.resource<const LightBuffer>();
  a.self_shadow = shadows->method != ShadowMethod::none;
  a.scattering = shadows->scattering;
  world.each<const AnisotropicCloud>([&](ecs::Entity e, const AnisotropicCloud& c) {
    const ParticleLight* light = world.try_get<const ParticleLight>(e);
    const size_t start = a.others_depth.size();
    a.others_depth.resize(start + c.particles.size(), glm::vec4(0.0f));
    if (light && light->others_depth.size() == c.particles.size())
      std::copy(light->others_depth.begin(), light->others_depth.end(), a.others_depth.begin() + long(start));
  });
  return a;
}

// After the other particles, into the target they were drawn into (a view's layer, prepared
// by them, or its scene target).
void draw_anisotropic_clouds(ecs::World& world, bool layers_prepared) {
  AnisotropicSplatPass* pass = world.try_resource<AnisotropicSplatPass>();
  if (!pass) return;
  const View& view = world.resource<const View>();
  GpuFrame& frame = world.resource<GpuFrame>();
  const size_t views = std::min(view.eyes.size(), frame.eyes.size());
  const std::optional<AnisotropicLighting> lighting = anisotropic_lighting(world);
  for (size_t v = 0; v < views; ++v) {
    const gpu::GpuPassScope scope("anisotropic particles", true);  // profiling hook
    const EyeTargets& t = frame.eyes[v];
    pass->renderer.draw(view.eyes[v], t.layer && layers_prepared ? *t.layer : *t.scene,
                        lighting ? &*lighting : nullptr);
  }
}

// SortDevice::automatic: while the CPU orders a list the GPU could, and the choice was not
// measured at this many particles, time the GPU's order of the first list against the sorting
// system's CPU time per order this frame (its keys and radix order) and keep the faster; on the
// second frame at this count (SortDeviceChoice::steady).
void measure_sort_devices(ecs::World& world, BillboardRenderer& renderer, const EyeDrawLists& lists,
                          const RenderSettings& settings) {
  if (settings.sort_device != SortDevice::automatic || lists.eyes.empty()) return;
  const DrawList& list = lists.eyes[0];
  const SortScratch* scratch = world.try_resource<const SortScratch>();
  if (list.on_gpu || !list.gpu_request || !scratch) return;
  uint64_t particles = 0;
  for (const ParticlePool* p : lists.pools) particles += p->size();
  SortDeviceChoice& choice = world.resource<SortDeviceChoice>();
  const bool steady = choice.steady(particles);
  choice.last_frame_particles = particles;
  if (particles == 0 || !steady || !choice.needs_measuring(particles)) return;
  // One order serves every eye facing the viewplane; facing the viewpoint, one per eye.
  const size_t orders = settings.alignment == BillboardAlignment::viewplane ? 1 : lists.eyes.size();
  choice.cpu_ms = (scratch->times.keys_ms + scratch->times.order_ms) / double(orders);
  choice.gpu_ms = renderer.time_gpu_order(list, lists.pools);
  choice.gpu = choice.gpu_ms < choice.cpu_ms;
  choice.measured = true;
  choice.particles = particles;
}

// Lit media (a ShadowSettings resource): the splats' lighting from the light phase.
std::optional<SplatLighting> splat_lighting(ecs::World& world, const EyeDrawLists& lists) {
  const ShadowSettings* shadows = world.try_resource<const ShadowSettings>();
  if (!shadows) return std::nullopt;
  SplatLighting s;
  s.lights = lists.lights;
  s.scene = &world.resource<const LightBuffer>();
  s.self_shadow = shadows->method != ShadowMethod::none;
  s.sunlight = shadows->splat_sunlight;
  s.scattering = shadows->scattering;
  if (shadows->method == ShadowMethod::shadow_map) s.map = world.try_resource<const ShadowVolume>();
  return s;
}

// Entries [begin, end) of a gathered list's centres and colours, into `run`.
void copy_run(const DrawList& list, size_t begin, size_t end, DrawList& run) {
  run.center_radius.assign(list.center_radius.begin() + long(begin), list.center_radius.begin() + long(end));
  run.color_density.assign(list.color_density.begin() + long(begin), list.color_density.begin() + long(end));
}

// A mixed scene (components/particle_kind.h): the sorting system's one back-to-front list of
// every set, drawn in runs of one kind, each run by its kind's renderer into the same target.
// Both renderers blend premultiplied "over" (particle_blending.h), so drawing the runs in list
// order composites particles of different kinds that overlap in depth exactly as one list of one
// kind would be. A run costs an upload and a draw call: the cost grows with how often the kind
// changes along the order (sets apart in depth make few runs, interleaved ones many).
void draw_mixed_view(ecs::World& world, const DrawList& list, const CameraFrame& frame,
                     EyeTargets& t, const RenderSettings& settings) {
  const gpu::GpuPassScope pass("particle layer", true);  // profiling hook
  if (t.layer) prepare_layer(t);
  const gpu::RenderTarget& target = t.layer ? *t.layer : *t.scene;
  BillboardRenderer& splats = world.resource<BillboardRenderer>();
  SphereBillboardRenderer& spheres = world.resource<SphereBillboardRenderer>();
  DrawList run;
  for (size_t begin = 0, end = 0; begin < list.shapes.size(); begin = end) {
    const ParticleShape shape = list.shapes[begin];
    while (end < list.shapes.size() && list.shapes[end] == shape) ++end;
    copy_run(list, begin, end, run);
    if (shape == ParticleShape::gaussian)
      splats.draw(run, {}, frame, target, settings.alignment, BillboardShading::kernel, nullptr);
    else
      spheres.draw(run, frame, target, t.scene->depth_texture(), t.scene->width(), t.scene->height(),
                   shape == ParticleShape::planar, settings.billboard_sprites);
  }
}

// Returns whether the views' layers were prepared (cleared, the scene's depth copied down).
bool draw_particle_lists(ecs::World& world) {
  const EyeDrawLists* lists = world.try_resource<const EyeDrawLists>();
  if (!lists) return false;
  const View& view = world.resource<const View>();
  GpuFrame& frame = world.resource<GpuFrame>();
  const RenderSettings& settings = world.resource<const RenderSettings>();
  const size_t views = std::min({view.eyes.size(), frame.eyes.size(), lists->eyes.size()});
  const std::optional<ParticleShape> common = common_particle_shape(world, settings.particles);
  if (common == ParticleShape::gaussian) {
    BillboardRenderer& renderer = world.resource<BillboardRenderer>();
    measure_sort_devices(world, renderer, *lists, settings);
    renderer.reset_cost();
    const std::optional<SplatLighting> lighting = splat_lighting(world, *lists);
    for (size_t v = 0; v < views; ++v)
      draw_particles_for_view(renderer, *lists, v, view.eyes[v], frame.eyes[v], settings.alignment,
                              BillboardShading::kernel, lighting ? &*lighting : nullptr);
    return true;
  }
  if (settings.media_layers()) {
    draw_media(world, *lists, view, frame, settings, views);
    return false;
  }
  if (!common) {
    for (size_t v = 0; v < views; ++v) draw_mixed_view(world, lists->eyes[v], view.eyes[v], frame.eyes[v], settings);
    return true;
  }
  SphereBillboardRenderer& spheres = world.resource<SphereBillboardRenderer>();
  for (size_t v = 0; v < views; ++v) {
    EyeTargets& t = frame.eyes[v];
    const gpu::GpuPassScope pass("particle layer", true);  // profiling hook
    if (t.layer) prepare_layer(t);
    spheres.draw(lists->eyes[v], view.eyes[v], t.layer ? *t.layer : *t.scene,
                 t.scene->depth_texture(), t.scene->width(), t.scene->height(),
                 *common == ParticleShape::planar, settings.billboard_sprites);
  }
  return true;
}

void draw_billboards(ecs::World& world) {
  draw_anisotropic_clouds(world, draw_particle_lists(world));
}

}  // namespace

ecs::SystemDesc billboard_render_system() {
  using Renderers =
      ecs::Writes<BillboardRenderer, ExplosionRenderer, SphereBillboardRenderer, AnisotropicSplatPass>;
  return {.name = "billboard_render",
          .phase = ecs::Phase::render,
          .access = ecs::Access::of<
              ecs::Reads<EyeDrawLists, View, RenderSettings, LightBuffer, FrameClock,
                         ExplosionShading, AnisotropicCloud, ParticleSet, ParticleKind, ParticleLight, SortScratch, ShadowSettings, ShadowVolume,
                         FireLights, MeshShadow>,
              ecs::Writes<GpuFrame, SortDeviceChoice>, Renderers>(),
          .run = draw_billboards,
          .setup = make_particle_renderer,
          // Blends over what the opaque and flipbook passes drew.
          .after = {"flipbook_render"},
          .main_thread = true};
}

}  // namespace pyro
