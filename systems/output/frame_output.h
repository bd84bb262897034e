#pragma once
// The sinks' common frame: one output folder (engine/io/output_folder.h: its lock, manifest,
// staging folder and --resume rules) shared by every sink of a run. Each output frame is read
// back once (output_frame.h) and handed to every sink, which writes into the staging folder; the
// run's files are moved in together by commit(), so a failure (a full disk, a kill) at any point
// leaves the folder as it was.
#include <memory>
#include <string>
#include <vector>

#include "engine/io/output_folder.h"
#include "systems/output/frame_sink.h"

namespace pyro {

class FrameOutput {
 public:
  // `folder` has begun (OutputFolder::begin); with `resume`, frames it holds finished are kept.
  FrameOutput(OutputFolder& folder, bool resume) : folder_(folder), resume_(resume) {}

  void add(std::unique_ptr<FrameSink> sink) { sinks_.push_back(std::move(sink)); }

  // Every sink's files of frame `index`, as names inside the output folder.
  std::vector<std::string> files(int index) const;
  // The frames of first .. last to draw: all of them, but with `resume` those whose files the
  // folder holds finished for this run (unless a sink needs every frame).
  std::vector<int> frames_to_draw(int first, int last) const;
  // Hands frame `index`, just drawn by `source`, to every sink.
  void write(int index, FrameSource& source);
  // Finishes every sink, then moves the staged files in and writes the manifest.
  void commit();

 private:
  OutputFolder& folder_;
  bool resume_;
  std::vector<std::unique_ptr<FrameSink>> sinks_;
};

}  // namespace pyro
