#pragma once
// Render phase, the `billboard_render` system (after the opaque and flipbook passes): blends
// each view's sorted particles over its opaque frame, or into its reduced-resolution layer
// (composited later). Gaussian particles need a BillboardRenderer resource (made from the
// scene's footprint table); the system's setup makes the spherical or explosion renderer that
// the scene's particle shape needs.
#include "components/draw_list.h"
#include "components/gpu_frame.h"
#include "engine/ecs/schedule.h"
#include "systems/billboard_render/billboard_renderer.h"

namespace pyro {

// The Gaussian splats of view `eye` (lists.eyes[eye], reading lists.pools) into its layer or
// scene target.
void draw_particles_for_view(BillboardRenderer& renderer, const EyeDrawLists& lists, size_t eye,
                             const CameraFrame& frame, EyeTargets& targets,
                             BillboardAlignment alignment, BillboardShading shading);

// Readies a view's reduced-resolution layer: transparent, with the scene's depth point-sampled
// down so that opaque geometry still hides depth-tested particles.
void prepare_layer(EyeTargets& targets);

ecs::SystemDesc billboard_render_system();

}  // namespace pyro
