#pragma once
// Edits of JSON text that keep every byte outside the edited value: key order, spacing, line
// breaks and the spelling of untouched numbers ("0.50" stays "0.50"). The value's place is found
// by a small scanner over the text (strings with their escapes, nesting), never by writing the
// tree again, so an editor can change one value of a hand-written file and save it back.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace pyro {

// Bytes [begin, end) of `text`.
struct JsonTextSpan {
  std::size_t begin = 0, end = 0;
};

// The reference tokens of an RFC 6901 JSON pointer ("/a/b~1c~0" -> {"a", "b/c~"}; "" -> {});
// nullopt when it is not one (no leading "/", a "~" not followed by 0 or 1).
std::optional<std::vector<std::string>> split_json_pointer(std::string_view pointer);

// The RFC 6901 pointer of `tokens` ({"a", "b/c~"} -> "/a/b~1c~0"): split_json_pointer's inverse.
std::string json_pointer_text(const std::vector<std::string>& tokens);

// The span of the value at `pointer` in `text` (which must be valid JSON), without the
// whitespace around it; nullopt when there is no value there.
std::optional<JsonTextSpan> find_json_value(std::string_view text, std::string_view pointer);

// `value` written compactly on one line: arrays as [1, 2, 3], objects as {"a": 1, "b": 2}, a
// number that a float holds exactly in the shortest decimal that reads back as that float (0.1f
// as 0.1, not 0.100000001490116), other numbers as nlohmann writes them.
std::string compact_json_text(const nlohmann::json& value);

struct JsonTextEdit {
  std::string text;   // the edited text (empty when failed)
  std::string error;  // what was expected, when the edit cannot be made (empty on success)
  bool failed() const { return !error.empty(); }
};

// `text` (valid JSON) with the value at `pointer` set to `value`, written by compact_json_text:
//  - an existing value's bytes are replaced in place (a value equal to the present one, as
//    nlohmann compares them, keeps its text);
//  - a key missing from an existing object is added as the object's last key, indented like the
//    one before it and with the same spacing around its colon;
//  - anything else (a missing parent, an array index past the end or "-", a child of a number or
//    string, a malformed pointer, a value with a NaN or infinity) fails with a message.
// Every byte outside the replaced value (or the inserted member) is left as it was.
JsonTextEdit set_json_value(std::string_view text, std::string_view pointer,
                            const nlohmann::json& value);

}  // namespace pyro
