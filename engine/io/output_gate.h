#pragma once
// The one gate every output path of every command passes before any work, given every file and
// folder the command reads (docs/reliability.md, "The gate"). A refusal is a UserError naming the
// path and its option (exit 2), but for a folder the system will not let the command write into
// (read-only file system, no permission: IoError, exit 1, found before the work, not after it).
//  * An output is never an input, nor inside a folder the command reads, nor a folder that holds
//    an input: compared by device and inode, so symbolic and hard links name the same file.
//  * An output is absent, a regular file (file outputs) or a folder (folder outputs): a device
//    node, FIFO or socket is refused, "-" (standard output) where the command allows it aside.
//  * The folder a file output goes into exists (a folder output creates its missing parents),
//    and the folder written into takes writes.
//  * A folder output is replaced only when it is empty or holds an earlier output of its own kind
//    (folder_output_kind.h); one holding anything else is refused, naming what it holds, unless
//    `overwrite`, which keeps every file no output wrote.
//  * Two outputs of one command never share a path, and none lies inside a folder output.
// Sizes that the readers limit are checked up front with check_image_size.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "engine/io/folder_output_kind.h"

namespace pyro {

// A file or folder a command reads, with what it is for messages: "the scene file", "the volume
// file of s.json at /volumes/0", ...
struct NamedPath {
  std::string path;
  std::string what;
};

enum class OutputShape {
  file,       // one file, replaced whole
  folder,     // a folder output of a kind, replaced whole or added to by runs of its kind
  container,  // a folder the command writes its own named files into, leaving the rest alone
};

struct OutputPath {
  OutputPath(std::string path_, std::string option_, OutputShape shape_ = OutputShape::file,
             FolderOutputKind kind_ = {}, bool overwrite_ = false, bool stdout_allowed_ = false)
      : path(std::move(path_)), option(std::move(option_)), shape(shape_), kind(std::move(kind_)),
        overwrite(overwrite_), stdout_allowed(stdout_allowed_) {}

  std::string path;
  std::string option;  // how the command line names it: "--out", "--trace", "file", ...
  OutputShape shape = OutputShape::file;
  FolderOutputKind kind;        // folder outputs: what the folder holds
  bool overwrite = false;       // folder outputs: replace an output whatever else it holds
  bool stdout_allowed = false;  // "-" is standard output
};

class OutputGate {
 public:
  // A file or folder the command reads; "" and paths that do not exist are skipped.
  OutputGate& reads(const std::string& path, const std::string& what);
  OutputGate& reads(const std::vector<NamedPath>& inputs);
  OutputGate& writes(OutputPath output);
  OutputGate& writes_file(const std::string& path, const std::string& option);

  // Applies every rule to every output ("" outputs are skipped). Throws UserError or IoError.
  void check() const;

 private:
  std::vector<NamedPath> inputs_;
  std::vector<OutputPath> outputs_;
};

// The largest image side the engine's readers take (PNG, EXR, flipbook atlases).
inline constexpr int64_t kMaxImageSide = 16384;

// Throws UserError(option) when a `width` x `height` image (`what`) exceeds what the engine's
// readers take.
void check_image_size(const std::string& option, const std::string& what, int64_t width, int64_t height);

// Throws UserError(option) when `what` needs `bytes` of memory, over half the machine's.
void check_memory_need(const std::string& option, const std::string& what, int64_t bytes);

}  // namespace pyro
