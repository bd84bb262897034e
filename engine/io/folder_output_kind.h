#pragma once
// What a folder output holds, told apart from what the user keeps in it. A folder output (a
// baked flipbook, an atlas, a six-way bake, a particle sequence, a render) records in its
// manifest, `.pyro_manifest.json`, the kind of output it is and the files it wrote. A command may
// replace a folder that is empty or holds an earlier output of its own kind; everything the
// manifest does not name is the user's (output_gate.h): never removed, and a reason to refuse
// unless --overwrite.
#include <filesystem>
#include <string>
#include <vector>

namespace pyro {

struct FolderOutputKind {
  std::string name;  // recorded in the manifest: "flipbook", "atlas", "six-way", ...
  // Top-level names (one '*' matches any run of characters) that belong to the output besides its
  // manifest's files: records, staging folders of runs still going or killed.
  std::vector<std::string> own_names;
  // Outputs written before manifests: a folder without one whose every file matches these
  // (and that holds at least one) is an earlier output of this kind.
  std::vector<std::string> unrecorded_names;
  // Replaced whole by each run (a bake): files beside its own are refused unless --overwrite.
  // Else runs add to it (a render's frame ranges), keeping the files beside their own.
  bool replaced_whole = true;
};

struct FolderOutputContents {
  bool exists = false;
  std::string held_kind;              // the kind its manifest (or unrecorded files) says; "" none
  std::vector<std::string> outputs;   // relative paths of files an earlier output wrote
  std::vector<std::string> foreign;   // relative paths of every other file: the user's
};

// A render's folder (output_folder.h): runs of one scene add frame ranges to it, beside the
// user's files; a farm keeps its jobs in `.farm` and its checksums in SHA256SUMS.
inline FolderOutputKind render_output_kind() {
  return {"render", {".partial-*", ".farm", "SHA256SUMS"}, {}, false};
}

// The manifest's file name in a folder output.
inline constexpr const char* kFolderOutputManifest = ".pyro_manifest.json";

// Whether `name` matches `pattern`, in which one '*' matches any run of characters.
bool matches_output_name(const std::string& name, const std::string& pattern);

// Reads `folder`'s files (recursively; folders themselves are not counted) and sorts them into
// the outputs of an earlier run (of any kind a manifest names, or `kind`'s own and unrecorded
// names) and the rest. A manifest without "kind" but with a run identity is a render's.
FolderOutputContents read_folder_output(const std::filesystem::path& folder, const FolderOutputKind& kind);

// "thesis.txt, notes/draft.md and 3 more files": a few of `files` named, for a message.
std::string name_some_files(const std::vector<std::string>& files);

// Writes `folder`/.pyro_manifest.json naming `kind` and every file under `folder` (but the
// manifest), durably. Throws IoError.
void write_folder_output_manifest(const std::filesystem::path& folder, const FolderOutputKind& kind);

}  // namespace pyro
