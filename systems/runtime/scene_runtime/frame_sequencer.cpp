#include "systems/runtime/scene_runtime/frame_sequencer.h"

#include <stdexcept>
#include <string>

namespace pyro {

FrameSequencer::FrameSequencer(int substeps, bool motion_blur)
    : substeps_(substeps), motion_blur_(motion_blur) {
  if (substeps < 1) throw std::invalid_argument("FrameSequencer: substeps must be at least 1");
}

uint64_t FrameSequencer::runtime_frame(int output_frame) const {
  return static_cast<uint64_t>(output_frame) * static_cast<uint64_t>(substeps_);
}

void FrameSequencer::advance_to(FrameStepper& runtime, uint64_t target) const {
  while (runtime.frame() < target) runtime.simulate_step();
}

void FrameSequencer::draw(FrameStepper& runtime, int f) {
  if (f < next_ || runtime.frame() > runtime_frame(f))
    throw std::logic_error("FrameSequencer: frame " + std::to_string(f) +
                           " is behind the runtime (frames must ascend)");
  if (motion_blur_)
    for (int g = next_; g < f; ++g) {
      if (runtime.frame() > runtime_frame(g)) continue;  // already run past by the caller
      advance_to(runtime, runtime_frame(g));
      runtime.step();
    }
  advance_to(runtime, runtime_frame(f));
  runtime.step();
  next_ = f + 1;
}

void FrameSequencer::draw(FrameStepper& runtime, const FrameRange& range,
                          const std::function<void(int)>& on_frame) {
  for (int f = range.first; f <= range.last; ++f) {
    draw(runtime, f);
    if (on_frame) on_frame(f);
  }
}

}  // namespace pyro
