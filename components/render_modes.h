#pragma once
// How particles are drawn: the choices a scene file (`render.billboards`, `render.particles`,
// `render.shading`, `render.sort_device`) and the command line make, read by the render systems.
#include "engine/core/enum_names.h"

namespace pyro {

// How particle billboards are oriented (Johnson & McAllister 2005, section 3): all facing the
// viewplane (one rotation per eye) or each facing the viewpoint (one rotation per particle).
enum class BillboardAlignment { viewplane, viewpoint };
inline constexpr EnumName<BillboardAlignment> billboard_alignment_names[] = {
    {BillboardAlignment::viewplane, "viewplane"}, {BillboardAlignment::viewpoint, "viewpoint"}};
constexpr const auto& enum_names(BillboardAlignment) { return billboard_alignment_names; }

// What a particle is when drawn: a Gaussian splat (Johnson & McAllister 2005: density is the
// opacity at the kernel's centre), or a sphere of homogeneous medium (Umenhoffer et al. 2006:
// density is the extinction coefficient tau, per unit length) drawn as a spherical billboard
// (opacity from the real path length, clipped by the scene and the near plane) or as the planar
// billboard it replaces (for comparison: it clips against geometry and pops at the near plane).
enum class ParticleShape { gaussian, spherical, planar };
inline constexpr EnumName<ParticleShape> particle_shape_names[] = {
    {ParticleShape::gaussian, "gaussian"},
    {ParticleShape::spherical, "spherical"},
    {ParticleShape::planar, "planar"}};
constexpr const auto& enum_names(ParticleShape) { return particle_shape_names; }

// color: each particle its own colour; explosion: dust, smoke and fire shaded by Umenhoffer et
// al. 2006's eq. 1, each medium in its own layer (spherical or planar particles only).
enum class ParticleShading { color, explosion };
inline constexpr EnumName<ParticleShading> particle_shading_names[] = {
    {ParticleShading::color, "color"}, {ParticleShading::explosion, "explosion"}};
constexpr const auto& enum_names(ParticleShading) { return particle_shading_names; }

// Where the Gaussian splats' draw order is made (culling and sorting): on the CPU
// (systems/sorting), on the GPU by compute shaders (systems/gpu_sorting), or on whichever of the
// two measured faster on this renderer (components/sort_device_choice.h). Both give the same
// order, so the images are the same bytes.
enum class SortDevice { automatic, cpu, gpu };
inline constexpr EnumName<SortDevice> sort_device_names[] = {
    {SortDevice::automatic, "auto"}, {SortDevice::cpu, "cpu"}, {SortDevice::gpu, "gpu"}};
constexpr const auto& enum_names(SortDevice) { return sort_device_names; }

}  // namespace pyro
