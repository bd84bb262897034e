#pragma once
// The particles a particle sequence draws at one scene frame: the two source frames around the
// current time (sequence_clock.h), read through a small window of loaded frames, cross-faded.
//
// The cross-fade. Frame a is drawn with its optical depths scaled by 1 - w and frame b with
// theirs scaled by w: a particle's centre opacity rho becomes 1 - (1 - rho)^f for weight f, i.e.
// tau0 = -ln(1 - rho) becomes f tau0. Extinction is linear in density, so the two scaled sets
// together are exactly the medium whose density is (1 - w) density_a + w density_b: the linear
// interpolation of the density field, which is what a renderer integrating optical depth (the
// lit splats, the CPU reference) then draws. Moving particles instead would need a
// correspondence between the frames' particles, which separate imports do not have (the octree
// makes each frame's particles afresh). Colours are not blended: each particle keeps its own.
#include <cstdint>

#include "components/volume_sequence.h"
#include "engine/particles/particle_pool.h"
#include "systems/volume_sequence/sequence_clock.h"

namespace pyro {

// A particle's centre opacity with its optical depth scaled by `weight` in [0, 1].
float faded_density(float density, double weight);

// The loaded frame `index`, read (and placed, and coloured) when not in the window; the least
// recently used frame is dropped when the window is full. Throws UserError naming the frame's
// file when it cannot be read, holds anisotropic particles, or holds another count than the
// manifest says.
const LoadedSequenceFrame& sequence_frame(VolumeSequence& sequence, std::size_t index);

// Fills `pool` (cleared first) with frame a at weight 1 - w then frame b at weight w, ids
// numbered from 0 (so the draw order's tie-breaks do not depend on earlier frames), and records
// the step in `sequence`. Throws std::length_error when the pool is too small.
void fill_sequence_particles(VolumeSequence& sequence, const SequenceSample& sample, ParticlePool& pool);

}  // namespace pyro
