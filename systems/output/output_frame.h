#pragma once
// One output frame as the output phase hands it to every sink (frame_sink.h): each form of the
// frame is read back from its source at most once, when the first sink asks for it, and shared by
// the others.
#include <optional>
#include <vector>

#include "systems/output/frame_source.h"

namespace pyro {

class OutputFrame {
 public:
  OutputFrame(int index, FrameSource& source) : index_(index), source_(source) {}

  // The output frame number (names the files: frame_names.h).
  int index() const { return index_; }
  const ShownImage& shown();
  // Read with depth when any sink asks for it (a second read only when depth is asked for after
  // a read without it).
  const std::vector<LinearView>& linear(bool with_depth);
  bool side_by_side() { return source_.shown_side_by_side(); }
  // The background to take out of transparent frames (frame_source.h); nullopt: opaque frames.
  const std::optional<FrameBackground>& background();

 private:
  int index_;
  FrameSource& source_;
  std::optional<ShownImage> shown_;
  std::optional<std::vector<LinearView>> linear_;
  bool linear_has_depth_ = false;
  std::optional<std::optional<FrameBackground>> background_;
};

}  // namespace pyro
