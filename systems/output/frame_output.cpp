#include "systems/output/frame_output.h"

#include <set>

namespace pyro {

std::vector<std::string> FrameOutput::files(int index) const {
  std::vector<std::string> names;
  for (const auto& sink : sinks_)
    for (std::string& name : sink->files(index)) names.push_back(std::move(name));
  return names;
}

std::vector<int> FrameOutput::frames_to_draw(int first, int last) const {
  bool every_frame = !resume_;
  for (const auto& sink : sinks_) every_frame = every_frame || sink->needs_every_frame();
  std::set<std::string> done(folder_.held_files().begin(), folder_.held_files().end());
  done.insert(folder_.adopted_files().begin(), folder_.adopted_files().end());
  std::vector<int> frames;
  for (int f = first; f <= last; ++f) {
    bool finished = !every_frame;
    for (const std::string& name : files(f)) finished = finished && done.count(name) > 0;
    if (!finished) frames.push_back(f);
  }
  return frames;
}

void FrameOutput::write(int index, FrameSource& source) {
  OutputFrame frame(index, source);
  for (const auto& sink : sinks_) sink->write(frame, folder_.staging().path());
}

void FrameOutput::commit() {
  for (const auto& sink : sinks_) sink->finish();
  folder_.commit();
}

}  // namespace pyro
