#pragma once
// Which source frames of a particle sequence show at a scene frame, and how much of each.
//
// The source position is s = start + t * fps at scene time t (fps: source frames per scene
// second, the manifest's fps times the scene's `speed`), t = frame / runtime fps: computed from
// the frame number and the two rates, not from the clock's float time step, whose rounding
// (about 3e-8 relative) would grow with the frame number. Frames a = floor(s) and b = a + 1 are
// cross-faded with weights 1 - w and w, w = s - a. A looping sequence wraps s into [0, count) and
// cross-fades its last frame into its first; one that does not loop holds its last frame once s
// reaches it. s is snapped to the nearest integer within 1e-6 s, so that a scene frame meant to
// land on a source frame draws that frame alone, whatever the rounding of the rates (a scene's
// fps is a float: 29.97 is stored 3e-8 off).
#include <cstddef>
#include <cstdint>

namespace pyro {

struct SequenceSample {
  std::size_t a = 0, b = 0;  // frame indices (equal when only one frame is drawn)
  double weight = 0.0;       // of frame b, in [0, 1); frame a's is 1 - weight
};

// The source position at runtime frame `frame` of a runtime running `runtime_fps` frames per
// second of scene time.
double sequence_position(uint64_t frame, double runtime_fps, double frames_per_second, std::size_t start);

// The frames around position s of a sequence of `count` frames (count >= 1, s >= 0).
SequenceSample sample_sequence(double s, std::size_t count, bool loop);

}  // namespace pyro
