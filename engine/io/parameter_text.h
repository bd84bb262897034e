#pragma once
// The text of parameter-file messages: numbers written short and exact, quoted values cut to a
// readable length, a JSON value described with its type, JSON pointer tokens (RFC 6901) and
// "did you mean" suggestions. Shared by every reader of JSON parameter files (the scene loader,
// the schema, an inspector) so that their messages read alike.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

namespace pyro {

// Shortest text that reads back as the same value (at float precision when `as_float`), with
// tidy exponents: 1e6 rather than 1000000 or 1e+06, 0.7 rather than 0.699999988.
std::string format_number(double v, bool as_float = false);
std::string format_float(float v);
std::string format_vec3(const glm::vec3& v);  // "[x, y, z]"

// `s` in double quotes, cut (its head and its size in bytes) when longer than 200 bytes.
std::string in_quotes(std::string_view s);
// "\"a\", \"b\", \"c\"".
std::string quoted_list(const std::vector<std::string_view>& items);

// What the user wrote, for "found ...": the value itself (shortened) and its JSON type.
std::string describe(const nlohmann::json& v);

// One JSON pointer token (RFC 6901: "~" -> "~0", "/" -> "~1"), cut like a quoted value when long.
std::string escape_pointer_token(std::string_view token);

// "; did you mean \"radius\"?" when a candidate is within two edits, else
// "; expected one of " and the full list.
std::string suggest(std::string_view wrong, const std::vector<std::string_view>& candidates);

}  // namespace pyro
