#pragma once
// A sink takes the output frames of a run, one after another, and writes them in its format:
// PNG frames (png_sink.h) and what an embedding program adds. The sinks' common frame
// (frame_output.h) gives every sink the same staging folder, manifest and --resume rules.
#include <filesystem>
#include <string>
#include <vector>

#include "systems/output/output_frame.h"

namespace pyro {

class FrameSink {
 public:
  virtual ~FrameSink() = default;
  // The files frame `index` becomes, as names inside the output folder (none for a sink that
  // writes elsewhere). A resumed run skips a frame whose files the folder already holds.
  virtual std::vector<std::string> files(int index) const = 0;
  // Whether the sink needs every frame of the range, those a resumed run keeps too (a video).
  virtual bool needs_every_frame() const { return false; }
  // Writes `frame`'s files into `staging` (the run's staging folder, moved into the output
  // folder when the run succeeds). Throws IoError when the file system refuses.
  virtual void write(OutputFrame& frame, const std::filesystem::path& staging) = 0;
  // After the range's last frame, before anything is moved in: a failure here still leaves the
  // output folder as it was.
  virtual void finish() {}
};

}  // namespace pyro
