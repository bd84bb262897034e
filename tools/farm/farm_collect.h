#pragma once
// The end of a farm job: the frames every task rendered into its chunk folder moved into the
// farm's output folder DIR, under DIR's lock and through its staging folder and manifest
// (engine/io/output_folder.h), as `pyro render` would have left them; then every frame of the
// job checked present for the job's identity and DIR/SHA256SUMS written (`sha256sum -c` reads
// it) once none is missing.
//
// A chunk folder is moved in only when its manifest holds the job's identity and no task holds
// its lock; the others are left as they are and named (still rendering, or another run). Every
// frame is read and checked against the SHA-256 its folder's manifest recorded when it was
// rendered: a damaged one (truncated, edited, another frame copied over it) is named, removed,
// never moved in nor written into SHA256SUMS, and counts as missing. A
// collect killed part-way is finished by the next one: frames it had moved into DIR's staging
// folder are taken up again (as `pyro render --resume` does), and a chunk's manifest is removed
// only after DIR's names its frames.
#include <set>
#include <string>
#include <vector>

#include "tools/farm/farm_record.h"
#include "systems/runtime/scene_runtime/runtime_options.h"

namespace pyro {

// The frame an output folder's file belongs to: "frame_0042.png", "frame_0042_left.exr" -> 42;
// -1 for any other name.
int frame_of_file(const std::string& name);

// Throws UserError naming `dir` when its manifest holds another run than `digest` (another scene,
// asset, settings or engine) or one of `replaceable` (the job's earlier identities, whose frames
// it replaces): a farm job never mixes its frames with another run's.
void refuse_other_run(const std::string& dir, const std::string& digest,
                      const std::vector<std::string>& replaceable = {});

struct FarmCollection {
  std::vector<FrameRange> missing;  // the job's frames DIR lacks, as ranges
  std::vector<std::string> files;   // the job's frame files in DIR, by name
  std::vector<std::string> damaged; // frame files whose bytes differ from their recorded SHA-256
  int moved = 0;                    // files this collect moved in from chunk folders
};

// Moves the finished chunks in, then checks the frames and writes DIR/SHA256SUMS when none is
// missing (removing an older one when some are: its presence says the job is complete). Notes
// (chunks left where they are, and why) go to `note`. Throws UserError for a DIR holding
// another run, IoError when the file system fails.
FarmCollection collect_farm(const std::string& dir, const FarmRecord& record, const NoteSink& note);

// The job's frames that are finished for its identity, in DIR or in a chunk folder not yet
// collected, with the bytes their manifest records: what `pyro farm resubmit` need not render
// again.
std::set<int> finished_farm_frames(const std::string& dir, const FarmRecord& record);

// The name of the checksum file collect writes into DIR.
inline constexpr const char* kFarmChecksumsName = "SHA256SUMS";

}  // namespace pyro
