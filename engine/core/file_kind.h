#pragma once
// What stands at a path where a command expects a regular file (a scene, a VDB or particle file,
// a cache): refused at once with what it is, never opened blindly (a FIFO without a writer would
// block the open forever; a folder or a symbolic link loop would fail later with a vaguer
// message).
#include <string>

namespace pyro {

// "" for a regular file (links followed); else what is there, for a message: "a folder",
// "a FIFO (named pipe)", "a socket", "a character device", "a block device",
// "a symbolic link loop", "no file", or "an unreadable path (OS error)".
std::string non_regular_file_kind(const std::string& path);

// True when `path` (links followed) is a FIFO: a pipe such as bash's <(...), or a named one.
bool is_fifo(const std::string& path);

}  // namespace pyro
