#pragma once
// pyro import-vdb PATTERN|GLOB|FOLDER --out NAME.pyroseq: an animated OpenVDB sequence imported
// into one particle sequence (systems/runtime/cloud_import/vdb_sequence_import.h), staged beside the
// output and put in its place only when every frame is written (engine/io/folder_replacement.h).
#include <string>

#include "engine/io/vdb_reader.h"

namespace pyro::cli {

struct SequenceImportArgs {
  std::string input, out;
  VdbGridChoice grid;
  double error = 0.03;
  double extinction = 0.0;  // 0: automatic, from the first frame with active voxels
  double fps = 24.0;
  bool json = false;
  bool overwrite = false;  // replace --out whatever else it holds (keeping those files)
};

void run_sequence_import(const SequenceImportArgs& args);

}  // namespace pyro::cli
