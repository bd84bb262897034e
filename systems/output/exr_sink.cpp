#include "systems/output/exr_sink.h"

#include <stdexcept>

#include "engine/io/exr_file.h"
#include "systems/output/frame_names.h"
#include "systems/output/transparent_frame.h"

namespace pyro {

std::vector<std::string> ExrSink::files(int index) const {
  std::vector<std::string> names;
  for (const std::string& stem : frame_view_stems(index, two_views_)) names.push_back(stem + ".exr");
  return names;
}

void ExrSink::write(OutputFrame& frame, const std::filesystem::path& staging) {
  const std::vector<LinearView>& views = frame.linear(depth_);
  const std::vector<std::string> names = files(frame.index());
  if (views.size() != names.size())
    throw std::logic_error("ExrSink: the source has " + std::to_string(views.size()) +
                           " view(s), the sink was made for " + std::to_string(names.size()));
  for (size_t v = 0; v < views.size(); ++v) {
    ExrImage image;
    image.width = views[v].width;
    image.height = views[v].height;
    image.rgba = views[v].rgba;
    if (frame.background()) remove_linear_background(image.rgba, frame.background()->linear);
    image.depth = views[v].depth;
    write_exr((staging / names[v]).string(), image);
  }
}

}  // namespace pyro
