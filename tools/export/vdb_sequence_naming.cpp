#include "tools/export/vdb_sequence_naming.h"

#include <cctype>
#include <cstdio>

#include "engine/core/user_error.h"

namespace pyro {

namespace {

bool name_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-'; }

}  // namespace

std::string vdb_frame_file_name(const std::string& name, int frame) {
  char number[32];
  std::snprintf(number, sizeof number, "%04d", frame + 1);
  return name + "." + number + ".vdb";
}

std::string vdb_sequence_pattern(const std::string& name) { return name + ".####.vdb"; }

void check_vdb_sequence_name(const std::string& name, const std::string& option) {
  bool ok = !name.empty() && name.size() <= 200;
  for (char c : name) ok = ok && name_char(c);
  if (!ok)
    throw UserError("", option,
                    "a sequence name of 1 to 200 letters, digits, '_' or '-' (the files are NAME.0001.vdb, ...), "
                    "found \"" + name + "\"");
}

std::string vdb_sequence_name_for(const std::string& scene_name) {
  std::string out;
  for (char c : scene_name) out += name_char(c) ? c : '_';
  if (out.size() > 200) out.resize(200);
  return out.empty() ? "media" : out;
}

}  // namespace pyro
