#pragma once
// The names of an exported VDB sequence and what its folder is as an output.
//
// Frame f of the scene (from 0) is written as NAME.NNNN.vdb with NNNN = f + 1, zero-padded to
// four digits (more past 9999): Blender's volume sequences take the number at the end of the file
// name and expect the first frame to be 1 (its Start field "assumes the first frame has a 1 in
// the file name"), and Houdini's frames count from 1 too and read NAME.$F4.vdb, its own
// convention for sequences (a File SOP or a Volume LOP). Both also read NAME_NNNN.vdb; the dot is
// Houdini's default and reads as one sequence in both.
#include <string>

#include "engine/io/folder_output_kind.h"

namespace pyro {

// "NAME.0001.vdb" for scene frame 0.
std::string vdb_frame_file_name(const std::string& name, int frame);

// The file name of frame `frame` as a host's pattern: "NAME.$F4.vdb" (Houdini), "NAME.####.vdb".
std::string vdb_sequence_pattern(const std::string& name);

// Throws UserError(option) unless `name` is 1 to 200 characters of letters, digits, '_' and '-'
// (no separators or dots, so that the frame number is the name's only number after a dot).
void check_vdb_sequence_name(const std::string& name, const std::string& option);

// A scene's name made into one check_vdb_sequence_name accepts ("media" when nothing is left).
std::string vdb_sequence_name_for(const std::string& scene_name);

// The export's folder: replaced whole by each export (engine/io/folder_replacement.h).
inline FolderOutputKind vdb_export_output_kind() { return {"vdb export", {".partial-*"}, {}}; }

}  // namespace pyro
