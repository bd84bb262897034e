#include "engine/io/json_text_edit.h"

#include <cmath>
#include <stdexcept>
#include <utility>

#include "engine/io/parameter_table.h"
#include "engine/io/parameter_text.h"

namespace pyro {
namespace {

using json = nlohmann::json;

// The scanner met text that is not JSON (the callers check the text first; this keeps every
// read in bounds whatever it is given).
struct NotJson : std::runtime_error {
  NotJson() : std::runtime_error("not JSON") {}
};

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

std::size_t skip_space(std::string_view t, std::size_t i) {
  while (i < t.size() && is_space(t[i])) ++i;
  return i;
}

char at(std::string_view t, std::size_t i) {
  if (i >= t.size()) throw NotJson();
  return t[i];
}

// The end of the string literal whose opening quote is t[i] (a backslash escapes the next byte).
std::size_t string_end(std::string_view t, std::size_t i) {
  for (++i; i < t.size(); ++i) {
    if (t[i] == '\\') {
      ++i;
    } else if (t[i] == '"') {
      return i + 1;
    }
  }
  throw NotJson();
}

// The end of the value that starts at t[i]: a string, an object or array (nesting counted,
// brackets inside strings skipped) or a literal (a number, true, false, null).
std::size_t value_end(std::string_view t, std::size_t i) {
  const char first = at(t, i);
  if (first == '"') return string_end(t, i);
  if (first == '{' || first == '[') {
    int depth = 0;
    while (i < t.size()) {
      const char c = t[i];
      if (c == '"') {
        i = string_end(t, i);
        continue;
      }
      if (c == '{' || c == '[') ++depth;
      if ((c == '}' || c == ']') && --depth == 0) return i + 1;
      ++i;
    }
    throw NotJson();
  }
  const std::size_t begin = i;
  while (i < t.size() && !is_space(t[i]) && t[i] != ',' && t[i] != ']' && t[i] != '}') ++i;
  if (i == begin) throw NotJson();
  return i;
}

struct Member {
  std::size_t key_begin = 0, key_end = 0;  // the key's literal, quotes included
  JsonTextSpan value;
};

// The members of the object spanning `object`, in the text's order.
std::vector<Member> object_members(std::string_view t, JsonTextSpan object) {
  std::vector<Member> members;
  std::size_t i = skip_space(t, object.begin + 1);
  if (at(t, i) == '}') return members;
  for (;;) {
    Member m;
    if (at(t, i) != '"') throw NotJson();
    m.key_begin = i;
    m.key_end = string_end(t, i);
    i = skip_space(t, m.key_end);
    if (at(t, i) != ':') throw NotJson();
    m.value.begin = skip_space(t, i + 1);
    m.value.end = value_end(t, m.value.begin);
    members.push_back(m);
    i = skip_space(t, m.value.end);
    if (at(t, i) == '}') return members;
    if (at(t, i) != ',') throw NotJson();
    i = skip_space(t, i + 1);
  }
}

// The elements of the array spanning `array`.
std::vector<JsonTextSpan> array_elements(std::string_view t, JsonTextSpan array) {
  std::vector<JsonTextSpan> elements;
  std::size_t i = skip_space(t, array.begin + 1);
  if (at(t, i) == ']') return elements;
  for (;;) {
    const std::size_t end = value_end(t, i);
    elements.push_back({i, end});
    i = skip_space(t, end);
    if (at(t, i) == ']') return elements;
    if (at(t, i) != ',') throw NotJson();
    i = skip_space(t, i + 1);
  }
}

// The key a member's literal stands for (escapes decoded).
std::string key_of(std::string_view t, const Member& m) {
  const std::string_view literal = t.substr(m.key_begin, m.key_end - m.key_begin);
  const std::string_view inside = literal.substr(1, literal.size() - 2);
  if (inside.find('\\') == std::string_view::npos) return std::string(inside);
  return json::parse(literal).get<std::string>();
}

// An RFC 6901 array index: "0" or digits without a leading zero; nullopt otherwise.
std::optional<std::size_t> array_index(const std::string& token) {
  if (token.empty() || token.size() > 18) return std::nullopt;
  if (token.size() > 1 && token[0] == '0') return std::nullopt;
  std::size_t n = 0;
  for (const char c : token) {
    if (c < '0' || c > '9') return std::nullopt;
    n = n * 10 + static_cast<std::size_t>(c - '0');
  }
  return n;
}

const Member* find_member(std::string_view t, const std::vector<Member>& members,
                          const std::string& key) {
  for (const Member& m : members) {
    if (key_of(t, m) == key) return &m;
  }
  return nullptr;
}

// The value named by `token` inside the value spanning `parent`; nullopt when there is none.
std::optional<JsonTextSpan> child(std::string_view t, JsonTextSpan parent, const std::string& token) {
  if (t[parent.begin] == '{') {
    const std::vector<Member> members = object_members(t, parent);
    if (const Member* m = find_member(t, members, token)) return m->value;
    return std::nullopt;
  }
  if (t[parent.begin] == '[') {
    const std::vector<JsonTextSpan> elements = array_elements(t, parent);
    const std::optional<std::size_t> index = array_index(token);
    if (index && *index < elements.size()) return elements[*index];
  }
  return std::nullopt;
}

JsonTextSpan root_span(std::string_view t) {
  const std::size_t begin = skip_space(t, 0);
  return {begin, value_end(t, begin)};
}

// RFC 6901 pointer text of the first `n` tokens.
std::string pointer_text(const std::vector<std::string>& tokens, std::size_t n) {
  return json_pointer_text(std::vector<std::string>(tokens.begin(), tokens.begin() + std::ptrdiff_t(n)));
}

std::string kind_of(const json& v) {
  if (v.is_null()) return "null";
  return std::string("a ") + v.type_name();
}

bool all_numbers_finite(const json& v) {
  if (v.is_number_float()) return std::isfinite(v.get<double>());
  if (v.is_structured()) {
    for (const json& child_value : v) {
      if (!all_numbers_finite(child_value)) return false;
    }
  }
  return true;
}

std::string splice(std::string_view t, JsonTextSpan span, std::string_view replacement) {
  std::string out;
  out.reserve(t.size() - (span.end - span.begin) + replacement.size());
  out.append(t.substr(0, span.begin));
  out.append(replacement);
  out.append(t.substr(span.end));
  return out;
}

// `members` (of a non-empty object) with a member `key`: `value_text` added after the last one,
// on its own line when the last one is, and with its spacing around the colon.
std::string add_member(std::string_view t, JsonTextSpan object, const std::vector<Member>& members,
                       const std::string& key, const std::string& value_text) {
  const std::string key_text = json(key).dump();
  if (members.empty()) {
    return splice(t, {object.begin + 1, object.begin + 1}, key_text + ": " + value_text);
  }
  const Member& last = members.back();
  std::size_t separator = last.key_begin;  // the '{' or ',' before the last key
  while (separator > object.begin && is_space(t[separator - 1])) --separator;
  std::string indent(t.substr(separator, last.key_begin - separator));
  if (members.size() == 1 && indent.find('\n') == std::string::npos) indent = " ";
  const std::string_view colon = t.substr(last.key_end, last.value.begin - last.key_end);
  const std::string member = "," + indent + key_text + std::string(colon) + value_text;
  return splice(t, {last.value.end, last.value.end}, member);
}

// The edit inside the container spanning `parent` (named by tokens[0, n-1)) at tokens[n-1].
JsonTextEdit set_in_parent(std::string_view t, JsonTextSpan parent,
                           const std::vector<std::string>& tokens, const json& value,
                           const std::string& value_text) {
  const std::string& token = tokens.back();
  const std::string parent_pointer = pointer_text(tokens, tokens.size() - 1);
  if (t[parent.begin] == '{') {
    const std::vector<Member> members = object_members(t, parent);
    if (const Member* m = find_member(t, members, token)) {
      const std::string_view old_text = t.substr(m->value.begin, m->value.end - m->value.begin);
      if (json::parse(old_text) == value) return {std::string(t), ""};
      return {splice(t, m->value, value_text), ""};
    }
    return {add_member(t, parent, members, token, value_text), ""};
  }
  if (t[parent.begin] == '[') {
    const std::vector<JsonTextSpan> elements = array_elements(t, parent);
    const std::optional<std::size_t> index = array_index(token);
    if (!index || *index >= elements.size()) {
      const std::string range = elements.empty()
                                    ? "none: the array is empty"
                                    : "0 to " + std::to_string(elements.size() - 1);
      return {"", "expected an index of the array at " + in_quotes(parent_pointer) + " (" + range +
                      "), found " + in_quotes(token)};
    }
    const JsonTextSpan old = elements[*index];
    if (json::parse(t.substr(old.begin, old.end - old.begin)) == value) return {std::string(t), ""};
    return {splice(t, old, value_text), ""};
  }
  const json scalar = json::parse(t.substr(parent.begin, parent.end - parent.begin));
  return {"", "expected an object or an array at " + in_quotes(parent_pointer) + ", found " +
                  kind_of(scalar)};
}

JsonTextEdit set_value(std::string_view t, const std::vector<std::string>& tokens,
                       const json& value, const std::string& value_text) {
  JsonTextSpan span = root_span(t);
  if (tokens.empty()) {
    if (json::parse(t) == value) return {std::string(t), ""};
    return {splice(t, span, value_text), ""};
  }
  for (std::size_t i = 0; i + 1 < tokens.size(); ++i) {
    const std::optional<JsonTextSpan> next = child(t, span, tokens[i]);
    if (!next) {
      return {"", "expected a value at " + in_quotes(pointer_text(tokens, i + 1)) +
                      " (only a missing key of an existing object is added), found none"};
    }
    span = *next;
  }
  return set_in_parent(t, span, tokens, value, value_text);
}

}  // namespace

std::optional<std::vector<std::string>> split_json_pointer(std::string_view pointer) {
  std::vector<std::string> tokens;
  if (pointer.empty()) return tokens;
  if (pointer[0] != '/') return std::nullopt;
  for (std::size_t i = 0; i < pointer.size(); ++i) {
    const char c = pointer[i];
    if (c == '/') {
      tokens.emplace_back();
    } else if (c != '~') {
      tokens.back() += c;
    } else if (i + 1 < pointer.size() && (pointer[i + 1] == '0' || pointer[i + 1] == '1')) {
      tokens.back() += pointer[++i] == '0' ? '~' : '/';
    } else {
      return std::nullopt;
    }
  }
  return tokens;
}

std::string json_pointer_text(const std::vector<std::string>& tokens) {
  std::string p;
  for (const std::string& token : tokens) {
    p += '/';
    for (const char c : token) {
      if (c == '~') {
        p += "~0";
      } else if (c == '/') {
        p += "~1";
      } else {
        p += c;
      }
    }
  }
  return p;
}

std::optional<JsonTextSpan> find_json_value(std::string_view text, std::string_view pointer) {
  const std::optional<std::vector<std::string>> tokens = split_json_pointer(pointer);
  if (!tokens) return std::nullopt;
  try {
    std::optional<JsonTextSpan> span = root_span(text);
    for (const std::string& token : *tokens) {
      span = child(text, *span, token);
      if (!span) return std::nullopt;
    }
    return span;
  } catch (const NotJson&) {
    return std::nullopt;
  }
}

std::string compact_json_text(const json& value) {
  if (value.is_array()) {
    std::string s = "[";
    for (std::size_t i = 0; i < value.size(); ++i) s += (i ? ", " : "") + compact_json_text(value[i]);
    return s + "]";
  }
  if (value.is_object()) {
    std::string s = "{";
    bool first = true;
    for (const auto& [key, member] : value.items()) {
      s += (first ? "" : ", ") + json(key).dump() + ": " + compact_json_text(member);
      first = false;
    }
    return s + "}";
  }
  if (value.is_number_float()) {
    const double d = value.get<double>();
    const float f = static_cast<float>(d);
    if (std::isfinite(d) && static_cast<double>(f) == d) return float_json(f).dump();
  }
  return value.dump();
}

JsonTextEdit set_json_value(std::string_view text, std::string_view pointer, const json& value) {
  const std::optional<std::vector<std::string>> tokens = split_json_pointer(pointer);
  if (!tokens) {
    return {"", "expected a JSON pointer (\"\", or \"/\" before each key or index, with \"~\" "
                "written \"~0\" and \"/\" inside a key \"~1\"), found " + in_quotes(pointer)};
  }
  if (!all_numbers_finite(value)) return {"", "expected finite numbers, found NaN or infinity"};
  std::string value_text;
  try {
    value_text = compact_json_text(value);
  } catch (const json::exception&) {
    return {"", "expected UTF-8 text in the value's strings, found invalid bytes"};
  }
  if (!json::accept(text)) return {"", "expected JSON text to edit, found text that does not parse"};
  try {
    return set_value(text, *tokens, value, value_text);
  } catch (const NotJson&) {
    return {"", "expected JSON text to edit, found text that does not parse"};
  } catch (const json::exception&) {
    return {"", "expected UTF-8 text in the pointer's keys, found invalid bytes"};
  }
}

}  // namespace pyro
