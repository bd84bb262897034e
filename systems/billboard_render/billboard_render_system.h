#pragma once
// Render phase, the `billboard_render` system (after the opaque and flipbook passes): blends
// each view's sorted particles over its opaque frame, or into its reduced-resolution layer
// (composited later). Gaussian particles need a BillboardRenderer resource (made from the
// scene's footprint table); the system's setup makes the spherical or explosion renderer that
// the scene's particle shape needs. Static anisotropic clouds (components/anisotropic_cloud.h)
// are drawn after those particles into the same target, each view in its own back-to-front
// order (not interleaved with the other particles).
#include "components/draw_list.h"
#include "components/gpu_frame.h"
#include "engine/ecs/schedule.h"
#include "systems/billboard_render/anisotropic_splat_renderer.h"
#include "systems/billboard_render/billboard_renderer.h"

namespace pyro {

// The Gaussian splats of view `eye` (lists.eyes[eye], reading lists.pools) into its layer or
// scene target; lit by `lighting` when given.
void draw_particles_for_view(BillboardRenderer& renderer, const EyeDrawLists& lists, size_t eye,
                             const CameraFrame& frame, EyeTargets& targets,
                             BillboardAlignment alignment, BillboardShading shading,
                             const SplatLighting* lighting = nullptr);

// Readies a view's reduced-resolution layer: transparent, with the scene's depth point-sampled
// down so that opaque geometry still hides depth-tested particles.
void prepare_layer(EyeTargets& targets);

// The anisotropic clouds' pass, a world resource: made at setup, with every AnisotropicCloud's
// particles uploaded together (they are fixed after loading), when the world holds any.
struct AnisotropicSplatPass {
  AnisotropicSplatRenderer renderer;
};

ecs::SystemDesc billboard_render_system();

}  // namespace pyro
