#include "systems/output/output_frame.h"

namespace pyro {

const ShownImage& OutputFrame::shown() {
  if (!shown_) shown_ = source_.read_shown();
  return *shown_;
}

const std::vector<LinearView>& OutputFrame::linear(bool with_depth) {
  if (!linear_ || (with_depth && !linear_has_depth_)) {
    linear_ = source_.read_linear(with_depth);
    linear_has_depth_ = with_depth;
  }
  return *linear_;
}

const std::optional<FrameBackground>& OutputFrame::background() {
  if (!background_) background_ = source_.transparent_background();
  return *background_;
}

}  // namespace pyro
