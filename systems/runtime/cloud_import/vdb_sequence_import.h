#pragma once
// An animated OpenVDB sequence imported into one particle sequence (engine/io/particle_sequence.h)
// by streaming: every member is checked first, then each frame in turn is read (sparse, in a
// child process), imported by the octree (cloud_import.h, isotropic particles, as a scene's load
// of a .vdb: no fit, no measurement), written as an ordinary particle file and dropped. So memory
// holds one frame's grid and particles at a time, whatever the sequence's length.
//
// One medium for the whole sequence: the extinction is given, or chosen (default_extinction)
// from the first frame that has active voxels and kept for every frame, so density keeps its
// meaning from frame to frame. An empty frame (grids with no active voxels) is a frame of 0
// particles, not an error.
#include <cstdint>
#include <filesystem>
#include <vector>

#include "engine/core/progress_sink.h"
#include "engine/io/particle_sequence.h"
#include "engine/io/vdb_reader.h"
#include "systems/runtime/cloud_import/vdb_sequence_members.h"

namespace pyro {

struct VdbSequenceImportOptions {
  VdbGridChoice grid;
  double error = 0.03;       // image error target -> the octree's tolerance (tau_tolerance_for_error)
  double extinction = 0.0;   // 0: automatic, from the first frame with active voxels
  double fps = 24.0;         // the source's frames per second, recorded in the manifest
  int threads = 0;           // the importer's (0: hardware concurrency)
};

struct VdbSequenceImportReport {
  uint64_t frames = 0, empty_frames = 0;
  uint64_t particles = 0, particles_max = 0;  // over all frames; the most in one frame
  uint64_t active_voxels = 0;
  double check_seconds = 0, read_seconds = 0, import_seconds = 0, write_seconds = 0;
  uint64_t reader_peak_rss_bytes = 0;  // the largest of the reading children's
};

// Checks one member before anything is read: it is a regular file, its structure is whole
// (check_vdb_file_structure), and it holds the grid `choice` picks as a float grid. Throws
// UserError naming the file.
void check_vdb_sequence_member(const std::string& path, const VdbGridChoice& choice);

// check_vdb_sequence_member for every member, in order; `progress` (may be null) gets a step each.
void check_vdb_sequence_members(const std::vector<VdbSequenceMember>& members, const VdbGridChoice& choice,
                                ProgressSink* progress = nullptr, VdbSequenceImportReport* report = nullptr);

// Imports the members (checked first by check_vdb_sequence_members) one by one into `folder`
// (which must exist: a staging folder), writing frame_NNNNNN.pyrop per member and the manifest
// last. `progress` (may be null) gets one step per frame imported.
ParticleSequence import_vdb_sequence(const std::vector<VdbSequenceMember>& members,
                                     const VdbSequenceImportOptions& options,
                                     const std::filesystem::path& folder, ProgressSink* progress = nullptr,
                                     VdbSequenceImportReport* report = nullptr);

}  // namespace pyro
