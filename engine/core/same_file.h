#pragma once
// Outputs that would destroy their own inputs: every output path a command takes (--out, --trace,
// --json files, --keep) is compared with every input by file identity (device and inode, links
// followed), before any work, so that `import-vdb box.vdb --out box.vdb` or `render s.json
// --trace s.json` is refused instead of replacing the input.
#include <string>
#include <vector>

namespace pyro {

// True when both paths exist and name the same file (same device and inode, links followed).
bool same_file(const std::string& a, const std::string& b);

struct NamedPath {
  std::string path;
  std::string what;  // for the message: "the scene file", "the volume file at /volumes/0", ...
};

// Throws UserError(output, option, ...) when `output` is one of `inputs`.
void refuse_output_over_inputs(const std::string& output, const std::string& option,
                               const std::vector<NamedPath>& inputs);

// Throws UserError(output, option, ...) when `output`'s folder is `folder` (same device and
// inode), whose files belong to `owner` (e.g. "--out's frames and manifest").
void refuse_output_inside(const std::string& output, const std::string& option,
                          const std::string& folder, const std::string& owner);

}  // namespace pyro
