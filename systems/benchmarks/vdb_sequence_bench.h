#pragma once
// The animated VDB import's speed and memory against the sequence's length: a synthetic puff
// sequence (engine/volume/puff_sequence.h) of the longest length asked for is written once, and
// its first L frames are imported (systems/cloud_import/vdb_sequence_import.h) for each length L,
// each import in a child process of its own, so that each one's peak resident memory is its own
// (wait4), not the largest so far. A streaming import's peak does not grow with L.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/core/progress_sink.h"
#include "systems/scene_runtime/runtime_options.h"

namespace pyro {

struct VdbSequenceBenchOptions {
  std::vector<int> lengths{25, 100};  // frames imported, each >= 1
  int side = 64;                      // the puff's cube, voxels a side
  double error = 0.03;                // the import's error target
  std::string keep;                   // keep the sequence and the imports here (empty: a temporary folder)
  ProgressSink* progress = nullptr;
  NoteSink on_note;
};

// Fields: side, generate_seconds, frames_written, runs: one per length with frames, particles,
// particles_max, active_voxels, seconds, frames_per_second, check_seconds, read_seconds,
// import_seconds, write_seconds, peak_rss_bytes (the importing process), reader_peak_rss_bytes
// (the largest of its reading children's); peak_rss_ratio (longest run's over shortest's).
nlohmann::json bench_vdb_sequence(const VdbSequenceBenchOptions& options);

}  // namespace pyro
