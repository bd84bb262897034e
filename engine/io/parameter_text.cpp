#include "engine/io/parameter_text.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "engine/core/edit_distance.h"

namespace pyro {

using json = nlohmann::json;

namespace {

// A value longer than this is quoted cut (its first kQuotedHead bytes and its size), so that a
// message stays short whatever the input holds.
constexpr std::size_t kQuoteLimit = 200, kQuotedHead = 60;

// `s` cut to at most `n` bytes without splitting a UTF-8 sequence.
std::string_view utf8_head(std::string_view s, std::size_t n) {
  if (s.size() <= n) return s;
  while (n > 0 && (static_cast<unsigned char>(s[n]) & 0xC0) == 0x80) --n;
  return s.substr(0, n);
}

std::string cut_if_long(std::string_view s) {
  if (s.size() <= kQuoteLimit) return std::string(s);
  return std::string(utf8_head(s, kQuotedHead)) + "\u2026 (" + std::to_string(s.size()) + " bytes)";
}

}  // namespace

// Shortest text that reads back as the same value (at float precision when `as_float`), with
// tidy exponents: 1e6 rather than 1000000 or 1e+06, 0.7 rather than 0.699999988.
std::string format_number(double v, bool as_float) {
  char buffer[40];
  for (int precision = 1; precision <= 17; ++precision) {
    std::snprintf(buffer, sizeof buffer, "%.*g", precision, v);
    const double back = std::strtod(buffer, nullptr);
    if (as_float ? static_cast<float>(back) == static_cast<float>(v) : back == v) break;
  }
  std::string s = buffer;
  const std::size_t e = s.find('e');
  if (e != std::string::npos) {
    std::string exponent = s.substr(e + 1);
    const bool negative = exponent[0] == '-';
    std::size_t i = (exponent[0] == '+' || exponent[0] == '-') ? 1 : 0;
    while (i + 1 < exponent.size() && exponent[i] == '0') ++i;
    s = s.substr(0, e) + "e" + (negative ? "-" : "") + exponent.substr(i);
    // %g switches to an exponent early (180 -> 1.8e2); write whole numbers below 1e4 in full.
    if (std::fabs(v) < 1e4 && v == std::floor(v)) {
      std::snprintf(buffer, sizeof buffer, "%.0f", v);
      s = buffer;
    }
  } else if (v == std::floor(v) && std::fabs(v) >= 1e4) {
    // 1000000 -> 1e6 when it ends in at least four zeros.
    std::size_t zeros = 0;
    while (zeros < s.size() && s[s.size() - 1 - zeros] == '0') ++zeros;
    if (zeros >= 4) s = s.substr(0, s.size() - zeros) + "e" + std::to_string(zeros);
  }
  return s;
}

std::string format_float(float v) { return format_number(v, true); }

std::string format_vec3(const glm::vec3& v) {
  return "[" + format_float(v.x) + ", " + format_float(v.y) + ", " + format_float(v.z) + "]";
}

std::string in_quotes(std::string_view s) {
  // Built by appending: g++ 12 at -O3 warns falsely (-Wrestrict) on "\"" + std::string.
  const std::string text = cut_if_long(s);
  std::string q;
  q.reserve(text.size() + 2);
  q += '"';
  q += text;
  q += '"';
  return q;
}

std::string quoted_list(const std::vector<std::string_view>& items) {
  std::string out;
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (i > 0) out += ", ";
    out += in_quotes(items[i]);
  }
  return out;
}

// What the user wrote, for "found ...": the value itself (shortened) and its JSON type.
std::string describe(const json& v) {
  std::string text = v.dump(-1, ' ', false, json::error_handler_t::replace);
  if (text.size() > 60) text = std::string(utf8_head(text, 57)) + "...";
  switch (v.type()) {
    case json::value_t::null:
      return "null";
    case json::value_t::boolean:
      return text + " (boolean)";
    case json::value_t::string:
      return text + " (string)";
    case json::value_t::number_integer:
    case json::value_t::number_unsigned:
    case json::value_t::number_float:
      return text;
    case json::value_t::object:
      return text + " (object)";
    case json::value_t::array:
      return text + " (array of " + std::to_string(v.size()) + ")";
    default:
      return "a value of type " + std::string(v.type_name());
  }
}

// RFC 6901: "~" -> "~0", "/" -> "~1".
// A token longer than kQuoteLimit is cut like a quoted value.
std::string escape_pointer_token(std::string_view token) {
  std::string out;
  for (char c : cut_if_long(token)) {
    if (c == '~')
      out += "~0";
    else if (c == '/')
      out += "~1";
    else
      out += c;
  }
  return out;
}

// "; did you mean "radius"?" when a candidate is within two edits, else the full list.
std::string suggest(std::string_view wrong, const std::vector<std::string_view>& candidates) {
  const std::string_view best = closest_candidate(wrong, candidates);
  if (!best.empty()) return "; did you mean " + in_quotes(best) + "?";
  return "; expected one of " + quoted_list(candidates);
}

}  // namespace pyro
