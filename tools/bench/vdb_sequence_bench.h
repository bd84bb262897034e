#pragma once
// The animated VDB import's speed and memory against the sequence's length: for each length L,
// the synthetic puff's whole motion (engine/volume/puff_sequence.h) is written in L frames, so
// every length holds the same range of frame sizes, and imported
// (systems/runtime/cloud_import/vdb_sequence_import.h) in a child process of its own, so that each
// import's peak resident memory is its own, not the largest so far. A streaming import's peak
// does not grow with L.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/core/progress_sink.h"
#include "systems/runtime/scene_runtime/runtime_options.h"

namespace pyro {

struct VdbSequenceBenchOptions {
  std::vector<int> lengths{25, 100};  // frames imported, each >= 1
  int side = 64;                      // the puff's cube, voxels a side
  double error = 0.03;                // the import's error target
  std::string keep;                   // keep the sequence and the imports here (empty: a temporary folder)
  ProgressSink* progress = nullptr;
  NoteSink on_note;
};

// Fields: side, error_target, generate_seconds (every length's files), runs: one per length with frames, particles,
// particles_max, active_voxels, seconds, frames_per_second, check_seconds, read_seconds,
// import_seconds, write_seconds, importer_peak_rss_bytes (the importing process alone,
// getrusage), reader_peak_rss_bytes (the largest of its reading children's), peak_rss_bytes (the
// whole tree, wait4: the larger of the two); peak_rss_ratio (the longest run's importer peak over
// the shortest's).
nlohmann::json bench_vdb_sequence(const VdbSequenceBenchOptions& options);

}  // namespace pyro
