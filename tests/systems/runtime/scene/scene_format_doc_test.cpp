// docs/scene_format.md against the key tables (systems/runtime/scene/scene_keys.h): every key of every
// table is documented, every key the document's tables name is in a table, and where a row names
// one key, its default and range are the table's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/io/parameter_range.h"
#include "engine/io/parameter_table.h"
#include "engine/io/parameter_text.h"
#include "systems/runtime/scene/scene_keys.h"

namespace pyro {
namespace {

using json = nlohmann::json;

std::vector<std::string> doc_lines() {
  std::ifstream in(std::filesystem::path(PYRO_SOURCE_DIR) / "docs/scene_format.md");
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::string replace_all(std::string s, const std::string& from, const std::string& to) {
  for (std::size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size()))
    s.replace(at, from.size(), to);
  return s;
}

std::vector<std::string> cells(const std::string& row) {
  std::vector<std::string> out;
  std::stringstream s(row.substr(1));
  for (std::string cell; std::getline(s, cell, '|');) out.push_back(cell);
  return out;
}

std::vector<std::string> backticked(const std::string& text) {
  std::vector<std::string> out;
  static const std::regex token("`([^`]+)`");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), token); it != std::sregex_iterator(); ++it)
    out.push_back((*it)[1]);
  return out;
}

// The keys along `name` (possibly dotted: "fire.t_min") from `table`, else `name` in one of its
// nested tables (a table documented below its parent's rows, as groups[] below fires[]); empty
// when no table declares it.
std::vector<const ParameterKey*> resolve(const ParameterTable& table, const std::string& name) {
  std::vector<const ParameterKey*> path;
  const ParameterTable* t = &table;
  std::stringstream parts(name);
  for (std::string part; std::getline(parts, part, '.');) {
    const ParameterKey* k = t != nullptr ? t->find(part) : nullptr;
    if (k == nullptr) {
      path.clear();
      break;
    }
    path.push_back(k);
    t = k->table;
  }
  if (!path.empty() || name.find('.') != std::string::npos) return path;
  for (const ParameterKey& nested : table.keys)
    if (nested.table != nullptr)
      if (const ParameterKey* inner = nested.table->find(name)) return {inner};
  return {};
}

const ParameterTable* section_table(const std::string& heading) {
  if (heading == "### Top level") return &scene_keys();
  const std::vector<std::string> names = backticked(heading);
  if (names.empty()) return nullptr;
  std::string name = names[0];
  if (name.size() > 2 && name.substr(name.size() - 2) == "[]") name.resize(name.size() - 2);
  const ParameterKey* k = scene_keys().find(name);
  return k != nullptr ? k->table : nullptr;
}

bool same_default(const json& doc, const json& table) {
  if (table.is_array() && doc.is_number()) {  // a grey level for [c, c, c]
    for (const json& v : table)
      if (!same_default(doc, v)) return false;
    return true;
  }
  if (table.is_number() && doc.is_number())
    return std::fabs(doc.get<double>() - table.get<double>()) <= 1e-6 * std::max(1.0, std::fabs(table.get<double>()));
  if (table.is_array() && doc.is_array() && table.size() == doc.size()) {
    for (std::size_t i = 0; i < table.size(); ++i)
      if (!same_default(doc[i], table[i])) return false;
    return true;
  }
  return doc == table;
}

// The key's range as the document may write it: "[1, 1e7]" or "[1, 10000000]", "[0, 2⁶⁴-1]".
std::vector<std::string> expected_ranges(const ParameterKey& k) {
  if (k.type != ParameterType::integer) return {k.range.text()};
  if (k.integer_max == std::numeric_limits<std::uint64_t>::max())
    return {"[" + std::to_string(k.integer_min) + ", 2⁶⁴-1]"};
  return {"[" + std::to_string(k.integer_min) + ", " + format_number(static_cast<double>(k.integer_max)) + "]",
          "[" + std::to_string(k.integer_min) + ", " + std::to_string(k.integer_max) + "]"};
}

// The checks of one row that names a single key: its default and range.
void check_row(const ParameterKey& k, const std::vector<std::string>& c, const std::string& row) {
  const std::string default_cell = replace_all(c[2], "−", "-");
  const std::string range_cell = replace_all(c[3], "−", "-");
  if (!k.default_value.is_null() && k.type != ParameterType::string) {
    const std::vector<std::string> tokens = backticked(default_cell);
    const json doc = tokens.empty() ? json() : json::parse(tokens[0], nullptr, false);
    EXPECT_TRUE(same_default(doc, k.default_value))
        << "the default of `" << k.name << "` is " << k.default_value.dump() << " in its table: " << row;
  }
  const bool ranged = k.type == ParameterType::number || k.type == ParameterType::integer ||
                      k.type == ParameterType::vec3;
  if (ranged && !(range_cell.find("any") != std::string::npos && k.range.lo == -kLarge)) {
    const std::vector<std::string> ranges = expected_ranges(k);
    EXPECT_TRUE(std::any_of(ranges.begin(), ranges.end(),
                            [&](const std::string& r) { return range_cell.find(r) != std::string::npos; }))
        << "the range of `" << k.name << "` is " << ranges[0] << " in its table: " << row;
  }
  if (k.type == ParameterType::choice) {
    for (std::string_view name : k.choices) {
      EXPECT_NE(range_cell.find("\"" + std::string(name) + "\""), std::string::npos)
          << "`" << k.name << "` takes \"" << name << "\": " << row;
    }
  }
}

// Every key reachable from `table`, with the rows and prose that document it.
void collect_keys(const ParameterTable& table, std::vector<std::pair<const ParameterTable*, const ParameterKey*>>& out) {
  for (const ParameterKey& k : table.keys) {
    out.push_back({&table, &k});
    if (k.table != nullptr) collect_keys(*k.table, out);
  }
}

TEST(SceneFormatDoc, TheDocumentsKeyTablesAreTheLoadersKeyTables) {
  std::set<const ParameterKey*> documented;
  std::map<const ParameterTable*, std::string> documenting_text;  // rows and prose naming a table's keys
  const ParameterTable* section = nullptr;
  const ParameterTable* prose_table = nullptr;
  int rows = 0;
  for (const std::string& line : doc_lines()) {
    if (line.rfind("### ", 0) == 0) section = section_table(line);
    if (section == nullptr) continue;
    // "`scattering` keys: ..." documents a nested table in prose, up to the next blank line.
    static const std::regex prose("^`([a-z_]+)` keys:");
    std::smatch m;
    if (std::regex_search(line, m, prose)) {
      const ParameterKey* k = section->find(m[1].str());
      prose_table = k != nullptr ? k->table : nullptr;
    }
    if (line.empty()) prose_table = nullptr;
    if (prose_table != nullptr) documenting_text[prose_table] += line;
    if (line.rfind("| `", 0) != 0) continue;
    const std::vector<std::string> c = cells(line);
    ASSERT_GE(c.size(), 5u) << line;
    const std::vector<std::string> names = backticked(c[0]);
    for (const std::string& name : names) {
      const std::vector<const ParameterKey*> path = resolve(*section, name);
      EXPECT_FALSE(path.empty()) << "the document names `" << name << "`, which no key table declares: " << line;
      if (path.empty()) continue;
      documented.insert(path.begin(), path.end());
      const ParameterKey* k = path.back();
      if (k->table != nullptr) documenting_text[k->table] += line;
      if (names.size() == 1) check_row(*k, c, line);
      ++rows;
    }
  }
  std::vector<std::pair<const ParameterTable*, const ParameterKey*>> keys;
  collect_keys(scene_keys(), keys);
  int missing = 0;
  for (const auto& [table, key] : keys) {
    if (documented.count(key) != 0) continue;
    // A nested table's keys may be named in its parent's row or prose: "time", `time` or .time.
    const std::regex named("[\"`.]" + std::string(key->name) + "[\"`]");
    const auto text = documenting_text.find(table);
    const bool in_text = text != documenting_text.end() && std::regex_search(text->second, named);
    EXPECT_TRUE(in_text) << "`" << table->name << "." << key->name << "` is not in docs/scene_format.md";
    missing += in_text ? 0 : 1;
  }
  std::printf("docs/scene_format.md: %d rows checked against %zu keys, %d undocumented\n", rows, keys.size(),
              missing);
}

}  // namespace
}  // namespace pyro
