#include "systems/runtime/cloud_import/vdb_sequence_members.h"

#include <fnmatch.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "engine/core/user_error.h"

namespace fs = std::filesystem;

namespace pyro {

namespace {

// A printf pattern's one conversion: "%d", "%6d" or "%06d" between a prefix and a suffix.
struct PrintfPattern {
  std::string prefix, suffix, conversion;
  std::string print(int64_t n) const {
    char digits[48];
    std::snprintf(digits, sizeof digits, conversion.c_str(), static_cast<long long>(n));
    return prefix + digits + suffix;
  }
};

std::optional<PrintfPattern> printf_pattern(const std::string& name) {
  const std::size_t at = name.find('%');
  if (at == std::string::npos) return std::nullopt;
  std::size_t i = at + 1;
  while (i < name.size() && std::isdigit(static_cast<unsigned char>(name[i]))) ++i;
  if (i >= name.size() || name[i] != 'd' || i - at > 4) return std::nullopt;
  if (name.find('%', i) != std::string::npos) return std::nullopt;
  return PrintfPattern{name.substr(0, at), name.substr(i + 1), name.substr(at, i - at) + "lld"};
}

bool has_glob(const std::string& name) { return name.find_first_of("*?[") != std::string::npos; }

// The last run of digits in a file's stem, with its position, or nullopt.
struct DigitRun {
  std::size_t at = 0, length = 0;
  int64_t value = 0;
};
std::optional<DigitRun> last_digits(const std::string& name) {
  const std::string stem = fs::path(name).stem().string();
  std::size_t end = stem.size();
  while (end > 0 && !std::isdigit(static_cast<unsigned char>(stem[end - 1]))) --end;
  std::size_t begin = end;
  while (begin > 0 && std::isdigit(static_cast<unsigned char>(stem[begin - 1]))) --begin;
  if (begin == end || end - begin > 15) return std::nullopt;
  return DigitRun{begin, end - begin, std::stoll(stem.substr(begin, end - begin))};
}

bool has_vdb_extension(const fs::path& p) {
  std::string ext = p.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == ".vdb";
}

// The regular files of `folder` whose names `keep` accepts, sorted by name.
template <class Keep>
std::vector<fs::path> files_in(const std::string& input, const fs::path& folder, Keep keep) {
  std::error_code ec;
  if (!fs::is_directory(folder, ec))
    throw UserError(input, "", "a sequence in an existing folder, found no folder at \"" + folder.string() + "\"");
  std::vector<fs::path> out;
  for (const fs::directory_entry& e : fs::directory_iterator(folder, ec))
    if (keep(e.path().filename().string())) out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<VdbSequenceMember> numbered_by_digits(const std::string& input, const std::vector<fs::path>& files) {
  std::vector<VdbSequenceMember> members;
  for (const fs::path& f : files) {
    const std::optional<DigitRun> digits = last_digits(f.filename().string());
    if (!digits)
      throw UserError(input, "", "files numbered by frame (digits in each name), found \"" + f.string() +
                                     "\" with no frame number in its name");
    members.push_back({f.string(), digits->value});
  }
  return members;
}

std::vector<VdbSequenceMember> printf_members(const std::string& input, const fs::path& folder,
                                              const PrintfPattern& pattern) {
  std::vector<VdbSequenceMember> members;
  for (const fs::path& f : files_in(input, folder, [&](const std::string& name) {
         return name.size() > pattern.prefix.size() + pattern.suffix.size() &&
                name.compare(0, pattern.prefix.size(), pattern.prefix) == 0 &&
                name.compare(name.size() - pattern.suffix.size(), pattern.suffix.size(), pattern.suffix) == 0;
       })) {
    const std::string name = f.filename().string();
    const std::string middle = name.substr(pattern.prefix.size(), name.size() - pattern.prefix.size() - pattern.suffix.size());
    if (middle.empty() || middle.size() > 15 ||
        !std::all_of(middle.begin(), middle.end(), [](unsigned char c) { return std::isdigit(c); }))
      continue;
    const int64_t n = std::stoll(middle);
    if (pattern.print(n) == name) members.push_back({f.string(), n});
  }
  return members;
}

// The name a missing frame would have: the pattern's, or the lower neighbour's with its number
// replaced (at the same width).
std::string missing_name(const std::optional<PrintfPattern>& pattern, const fs::path& folder,
                         const VdbSequenceMember& below, int64_t n) {
  if (pattern) return (folder / pattern->print(n)).string();
  const fs::path p(below.path);
  const std::string name = p.filename().string();
  const DigitRun d = *last_digits(name);
  char digits[48];
  std::snprintf(digits, sizeof digits, "%0*lld", static_cast<int>(d.length), static_cast<long long>(n));
  return (p.parent_path() / (name.substr(0, d.at) + digits + name.substr(d.at + d.length))).string();
}

void check_numbering(const std::string& input, const std::optional<PrintfPattern>& pattern,
                     const fs::path& folder, const std::vector<VdbSequenceMember>& members) {
  for (std::size_t i = 1; i < members.size(); ++i) {
    const VdbSequenceMember &a = members[i - 1], &b = members[i];
    if (a.frame == b.frame)
      throw UserError(input, "", "one file per frame number, found \"" + a.path + "\" and \"" + b.path +
                                     "\" both numbered " + std::to_string(a.frame));
    if (b.frame != a.frame + 1)
      throw UserError(missing_name(pattern, folder, a, a.frame + 1), "",
                      "an existing member of the sequence " + input + " (frame " + std::to_string(a.frame + 1) +
                          ", between \"" + a.path + "\" and \"" + b.path +
                          "\"; frame numbers must be consecutive), found none");
  }
}

}  // namespace

bool names_vdb_sequence(const std::string& input) {
  std::error_code ec;
  const std::string name = fs::path(input).filename().string();
  return fs::is_directory(input, ec) || printf_pattern(name).has_value() || has_glob(name);
}

std::vector<VdbSequenceMember> find_vdb_sequence_members(const std::string& input) {
  const fs::path given(input);
  std::error_code ec;
  const bool folder_given = fs::is_directory(given, ec);
  const fs::path folder = folder_given ? given : (given.parent_path().empty() ? fs::path(".") : given.parent_path());
  const std::string name = given.filename().string();
  const std::optional<PrintfPattern> pattern = folder_given ? std::nullopt : printf_pattern(name);
  std::vector<VdbSequenceMember> members;
  if (pattern)
    members = printf_members(input, folder, *pattern);
  else if (folder_given)
    members = numbered_by_digits(input, files_in(input, folder, [](const std::string& n) {
                                   return has_vdb_extension(n) && n[0] != '.';
                                 }));
  else
    members = numbered_by_digits(input, files_in(input, folder, [&](const std::string& n) {
                                   return ::fnmatch(name.c_str(), n.c_str(), FNM_PERIOD) == 0;
                                 }));
  if (members.empty())
    throw UserError(input, "", std::string("at least one file of the sequence, found none ") +
                                   (folder_given ? "with a .vdb extension in the folder" : "matching the pattern") +
                                   " (\"" + folder.string() + "\")");
  std::stable_sort(members.begin(), members.end(),
                   [](const VdbSequenceMember& a, const VdbSequenceMember& b) { return a.frame < b.frame; });
  check_numbering(input, pattern, folder, members);
  return members;
}

}  // namespace pyro
