#pragma once
// The last layer of the runtime: which runtime steps make which output frames.
//  * Output frame f is the runtime's frame f * substeps (a quality pick's finer time step): the
//    steps in between only simulate (spawn and simulate phases), then one full step draws it.
//  * Frame f is the state after f output frames whatever frames are asked for: frames before
//    the first one asked for are simulated, not drawn...
//  * ...except with motion blur, where each output blends the frames drawn before it: then every
//    output frame before the asked one is drawn too (not returned), so that frames A..B of a
//    run equal the same frames of a full run, byte for byte.
#include <cstdint>
#include <functional>

#include "systems/runtime/scene_runtime/frame_range.h"

namespace pyro {

// What the sequencer drives (SceneRuntime; a recording fake in tests).
class FrameStepper {
 public:
  virtual ~FrameStepper() = default;
  virtual uint64_t frame() const = 0;  // the next runtime frame to run
  virtual void step() = 0;             // every phase, then frame() + 1
  virtual void simulate_step() = 0;    // spawn and simulate only, then frame() + 1
};

class FrameSequencer {
 public:
  // substeps >= 1.
  FrameSequencer(int substeps, bool motion_blur);

  int substeps() const { return substeps_; }
  bool motion_blur() const { return motion_blur_; }
  uint64_t runtime_frame(int output_frame) const;
  // The first output frame that draw() may still reach.
  int next_frame() const { return next_; }

  // Brings `runtime` to output frame f and draws it (the last step run draws f). Throws
  // std::logic_error when f < next_frame() or the runtime is already past f's runtime frame.
  void draw(FrameStepper& runtime, int f);
  // draw() for every frame of `range` in order, calling `on_frame(f)` after each.
  void draw(FrameStepper& runtime, const FrameRange& range, const std::function<void(int)>& on_frame);

 private:
  void advance_to(FrameStepper& runtime, uint64_t runtime_frame) const;

  int substeps_ = 1;
  bool motion_blur_ = false;
  int next_ = 0;
};

}  // namespace pyro
