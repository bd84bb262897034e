#pragma once
// A structural check of an OpenVDB file made before OpenVDB reads it. OpenVDB's reader trusts
// the offsets and lengths in a file: given a truncated copy it may read zeros past the end and
// return a partly empty grid, or loop for a long time. This check walks the header, the file
// metadata and the grid descriptors (OpenVDB file format, io/Archive.cc and io/GridDescriptor.cc:
// magic, version, library version, grid-offsets flag, UUID, metadata map, then per grid its
// name, type, instance parent and the byte offsets of its start, data blocks and end) and
// throws UserError(path, "", why) unless every length and offset lies inside the file and the
// last grid ends exactly at the end of the file. It does not decode the trees: damage inside a
// grid's data that keeps the length intact is left to OpenVDB's own checks.
#include <string>

namespace pyro {

void check_vdb_file_structure(const std::string& path);

}  // namespace pyro
