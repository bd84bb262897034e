#pragma once
// The files of an animated OpenVDB sequence, found from what `pyro import-vdb` was given:
//  - a printf pattern with one integer conversion (`smoke_%06d.vdb`, `smoke_%d.vdb`): every file
//    of the pattern's folder that the pattern prints for some frame number;
//  - a glob in the file name (`smoke_*.vdb`, `?`, `[...]`; fnmatch): the files it matches, each
//    numbered by the last run of digits in its name;
//  - a folder: every `.vdb` file in it, numbered alike.
// Members come back sorted by frame number (naturally: `smoke_10` after `smoke_9`). Numbers must
// be consecutive: a gap is refused, naming the file that is missing, because a gap is far more
// often a frame lost in a copy than a sequence meant to skip one (and playback would otherwise
// stretch the frames on either side across it).
#include <cstdint>
#include <string>
#include <vector>

namespace pyro {

struct VdbSequenceMember {
  std::string path;
  int64_t frame = 0;
};

// Whether `input` names a sequence (a folder, a printf pattern or a glob) rather than one file.
bool names_vdb_sequence(const std::string& input);

// The members, sorted by frame. Throws UserError(input, "", what was expected and what was
// found) when nothing matches, a name holds no frame number, two files have the same number, or
// a number is missing between the first and the last (naming the missing file).
std::vector<VdbSequenceMember> find_vdb_sequence_members(const std::string& input);

}  // namespace pyro
