#include "engine/io/output_gate.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <filesystem>
#include <optional>

#include "engine/core/file_kind.h"
#include "engine/core/user_error.h"
#include "engine/io/io_error.h"

namespace pyro {

namespace fs = std::filesystem;

namespace {

struct FileIdentity {
  dev_t device = 0;
  ino_t inode = 0;
  bool operator==(const FileIdentity& o) const { return device == o.device && inode == o.inode; }
};

std::optional<FileIdentity> identity_of(const fs::path& path) {
  struct stat s {};
  if (::stat(path.c_str(), &s) != 0) return std::nullopt;
  return FileIdentity{s.st_dev, s.st_ino};
}

// `path` made absolute with its symbolic links resolved as far as it exists.
fs::path resolved(const std::string& path) {
  std::error_code ec;
  fs::path p = fs::weakly_canonical(fs::absolute(path, ec), ec);
  return ec ? fs::absolute(path, ec).lexically_normal() : p;
}

// The identities of the folders above `path` that exist, nearest first.
std::vector<FileIdentity> folders_above(const std::string& path) {
  std::vector<FileIdentity> ids;
  fs::path p = resolved(path);
  while (p.has_relative_path()) {
    p = p.parent_path();
    if (auto id = identity_of(p)) ids.push_back(*id);
  }
  return ids;
}

bool contains(const std::vector<FileIdentity>& ids, const FileIdentity& id) {
  for (const FileIdentity& i : ids)
    if (i == id) return true;
  return false;
}

std::string folder_of_output(const std::string& path) {
  const fs::path parent = fs::path(path).parent_path();
  return parent.empty() ? "." : parent.string();
}

// An output's path holds nothing, a regular file (a file output) or a folder (a folder output).
void check_what_is_there(const OutputPath& o) {
  struct stat s {};
  if (::stat(o.path.c_str(), &s) != 0) {
    // Absent (or a dangling link, which a write replaces), or under a file: check_folder_written_into.
    if (errno == ENOENT || errno == ENOTDIR) return;
    throw UserError(o.path, o.option, "a path that can be written; it is " + non_regular_file_kind(o.path));
  }
  const bool folder_output = o.shape != OutputShape::file;
  if (S_ISDIR(s.st_mode) && !folder_output)
    throw UserError(o.path, o.option, "expected a file name for the output, found a folder");
  if (S_ISREG(s.st_mode) && folder_output)
    throw UserError(o.path, o.option, "expected a folder for the output, found a file");
  if (!S_ISDIR(s.st_mode) && !S_ISREG(s.st_mode))
    throw UserError(o.path, o.option, "an absent path, a regular file or a folder to write; it is " +
                                          non_regular_file_kind(o.path) +
                                          ", which is never replaced by an output");
}

// The folder the output goes into takes writes, checked before the work so that a read-only file
// system fails the command at once instead of after it. A file goes into an existing folder (or
// into a container output the command creates); a folder output creates its missing parents,
// under the nearest folder that exists.
void check_folder_written_into(const OutputPath& o, const std::vector<OutputPath>& all) {
  std::error_code ec;
  fs::path written = folder_of_output(o.path);
  if (o.shape == OutputShape::file) {
    for (const OutputPath& c : all)
      if (c.shape == OutputShape::container && resolved(c.path) == resolved(written) && !fs::exists(c.path, ec))
        return;  // checked as that output
    if (!fs::is_directory(written, ec))
      throw UserError(o.path, o.option, "an existing folder to write the output into, found " +
                                            std::string(fs::exists(written, ec) ? "a file" : "none") +
                                            " (\"" + written.string() + "\")");
  } else {
    written = fs::absolute(o.path, ec).lexically_normal();
    while (!fs::exists(written, ec) && written.has_relative_path()) written = written.parent_path();
    if (!fs::is_directory(written, ec))
      throw UserError(o.path, o.option, "a folder path, found a file at \"" + written.string() + "\"");
    const bool replaced_beside = o.shape == OutputShape::folder && o.kind.replaced_whole;
    if (written == fs::absolute(o.path, ec).lexically_normal() && replaced_beside)
      written = written.parent_path();  // its replacement is written beside it
  }
  if (::access(written.c_str(), W_OK) != 0) throw IoError(o.path, "write into \"" + written.string() + "\"", errno);
}

void check_against_inputs(const OutputPath& o, const std::vector<NamedPath>& inputs) {
  const std::optional<FileIdentity> self = identity_of(resolved(o.path));
  const std::vector<FileIdentity> above = folders_above(o.path);
  for (const NamedPath& input : inputs) {
    const std::optional<FileIdentity> in = identity_of(input.path);
    if (!in) continue;
    const std::string named = input.what + " (\"" + input.path + "\")";
    if (self && *self == *in)
      throw UserError(o.path, o.option, "an output path that is none of the command's inputs; it is " +
                                            named + ", which the output would replace");
    if (contains(above, *in))
      throw UserError(o.path, o.option, "an output path outside the folders the command reads; it lies "
                                        "inside " + named);
    if (self && o.shape != OutputShape::file && contains(folders_above(input.path), *self))
      throw UserError(o.path, o.option, "an output folder that holds none of the command's inputs; it "
                                        "holds " + named);
  }
}

// A folder output holds nothing, or an earlier output of its kind, or is to be overwritten.
void check_folder_contents(const OutputPath& o) {
  const FolderOutputContents c = read_folder_output(o.path, o.kind);
  if (!c.exists || o.overwrite) return;
  const std::string retry = " (pass --overwrite to replace the output and keep every other file, "
                            "or choose another folder)";
  if (!c.held_kind.empty() && c.held_kind != o.kind.name)
    throw UserError(o.path, o.option, "a folder that is empty or holds an earlier " + o.kind.name +
                                          " output; it holds a " + c.held_kind + " output" + retry);
  const bool kept_beside = c.held_kind == o.kind.name && !o.kind.replaced_whole;
  if (!c.foreign.empty() && !kept_beside)
    throw UserError(o.path, o.option, "a folder that is empty or holds an earlier " + o.kind.name +
                                          " output; it also holds " + name_some_files(c.foreign) +
                                          ", which no " + o.kind.name + " output wrote" + retry);
}

bool lies_inside(const fs::path& inner, const fs::path& folder) {
  const auto [f, i] = std::mismatch(folder.begin(), folder.end(), inner.begin(), inner.end());
  return f == folder.end() && i != inner.end();
}

// No two outputs share a path, and no output lies inside a folder output.
void check_outputs_apart(const OutputPath& a, const OutputPath& b) {
  const fs::path pa = resolved(a.path), pb = resolved(b.path);
  const std::optional<FileIdentity> ia = identity_of(pa), ib = identity_of(pb);
  if (pa == pb || (ia && ib && *ia == *ib))
    throw UserError(b.path, b.option, "a path of its own; it is also " + a.option + "'s, and one "
                                      "output would replace the other");
  const auto refuse_inside = [](const OutputPath& outer, const fs::path& outer_path, const OutputPath& inner,
                                 const fs::path& inner_path) {
    if (outer.shape == OutputShape::folder && lies_inside(inner_path, outer_path))
      throw UserError(inner.path, inner.option,
                      "an output path outside \"" + outer.path + "\", which holds " + outer.option +
                          "'s output; the file would be taken for part of it");
  };
  refuse_inside(a, pa, b, pb);
  refuse_inside(b, pb, a, pa);
}

bool skipped(const OutputPath& o) { return o.path.empty() || (o.stdout_allowed && o.path == "-"); }

}  // namespace

OutputGate& OutputGate::reads(const std::string& path, const std::string& what) {
  if (!path.empty() && path != "-") inputs_.push_back({path, what});
  return *this;
}

OutputGate& OutputGate::reads(const std::vector<NamedPath>& inputs) {
  for (const NamedPath& input : inputs) reads(input.path, input.what);
  return *this;
}

OutputGate& OutputGate::writes(OutputPath output) {
  outputs_.push_back(std::move(output));
  return *this;
}

OutputGate& OutputGate::writes_file(const std::string& path, const std::string& option) {
  return writes(OutputPath{path, option});
}

void OutputGate::check() const {
  for (size_t i = 0; i < outputs_.size(); ++i) {
    const OutputPath& o = outputs_[i];
    if (skipped(o)) continue;
    check_what_is_there(o);
    check_against_inputs(o, inputs_);
    for (size_t j = 0; j < i; ++j)
      if (!skipped(outputs_[j])) check_outputs_apart(outputs_[j], o);
    check_folder_written_into(o, outputs_);
    if (o.shape == OutputShape::folder) check_folder_contents(o);
  }
}

void check_image_size(const std::string& option, const std::string& what, int64_t width, int64_t height) {
  if (width < 1 || height < 1 || width > kMaxImageSide || height > kMaxImageSide)
    throw UserError(option, "", what + " of at most " + std::to_string(kMaxImageSide) + "x" +
                                    std::to_string(kMaxImageSide) + " pixels, the largest the engine's "
                                    "readers take; it would be " + std::to_string(width) + "x" +
                                    std::to_string(height));
}

void check_memory_need(const std::string& option, const std::string& what, int64_t bytes) {
  const int64_t memory = static_cast<int64_t>(::sysconf(_SC_PHYS_PAGES)) * ::sysconf(_SC_PAGE_SIZE);
  if (memory > 0 && bytes > memory / 2)
    throw UserError(option, "", what + " within half of this machine's memory (" +
                                    std::to_string(memory >> 20) + " MiB); they would need " +
                                    std::to_string(bytes >> 20) + " MiB");
}

}  // namespace pyro
