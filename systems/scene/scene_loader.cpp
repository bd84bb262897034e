// Scene file reader. Two layers:
//  1. JsonDocumentBuilder: a SAX handler that builds the JSON tree, turns syntax errors into
//     "line L, column C" places, and refuses duplicate keys (nlohmann would keep the last one
//     silently).
//  2. ObjectReader: walks one JSON object, knows its JSON pointer, reads typed and
//     range-checked values into the description (whose defaults stay when a key is absent),
//     remembers which keys it asked for and refuses any other key in finish().
// The scene-specific part at the bottom is then a list of one-line reads plus the few checks
// that involve several fields.
#include "systems/scene/scene_loader.h"

#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

#include "components/fire_lights.h"
#include "components/stereo_camera.h"
#include "engine/core/edit_distance.h"
#include "engine/core/file_kind.h"
#include "engine/core/long_json_string.h"
#include "engine/core/sha256.h"
#include "engine/core/user_error.h"

namespace pyro {
namespace {

using json = nlohmann::json;

// Bound on every quantity whose header comment gives no upper limit (lengths, coordinates,
// speeds, radiances, frame rate): far beyond any sensible scene, far below float overflow,
// and still coarse enough that float keeps ~0.1 world-unit precision at the extremes.
constexpr double kLarge = 1e6;

// ---------------------------------------------------------------------------------------------
// Text helpers

// Shortest text that reads back as the same value (at float precision when `as_float`), with
// tidy exponents: 1e6 rather than 1000000 or 1e+06, 0.7 rather than 0.699999988.
std::string format_number(double v, bool as_float = false) {
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

// nlohmann reports the 1-based index of the last byte it read (one past the end for an
// unexpected end of input). Columns count characters (UTF-8 lead bytes), starting at 1.
std::string line_and_column(const std::string& text, std::size_t position) {
  const std::size_t index = position > 0 ? position - 1 : 0;
  std::size_t line = 1, column = 1;
  for (std::size_t i = 0; i < index && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else if ((static_cast<unsigned char>(text[i]) & 0xC0) != 0x80) {
      ++column;
    }
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

// ---------------------------------------------------------------------------------------------
// JSON text -> tree

class JsonDocumentBuilder final : public nlohmann::json_sax<json> {
 public:
  explicit JsonDocumentBuilder(const std::string& text) : text_(text) {}

  json& root() { return root_; }
  bool failed() const { return failed_; }
  const std::string& error_place() const { return error_place_; }
  const std::string& error_message() const { return error_message_; }

  bool null() override { return put(nullptr) != nullptr; }
  bool boolean(bool v) override { return put(v) != nullptr; }
  bool number_integer(number_integer_t v) override { return put(v) != nullptr; }
  bool number_unsigned(number_unsigned_t v) override { return put(v) != nullptr; }
  bool number_float(number_float_t v, const string_t&) override { return put(v) != nullptr; }
  bool string(string_t& v) override { return put(std::move(v)) != nullptr; }
  bool binary(binary_t& v) override { return put(json::binary(std::move(v))) != nullptr; }

  bool start_object(std::size_t) override { return open(json::object()); }
  bool start_array(std::size_t) override { return open(json::array()); }
  bool end_object() override { return close(); }
  bool end_array() override { return close(); }

  bool key(string_t& k) override {
    json& object = *stack_.back();
    if (object.contains(k)) {
      return fail(current_pointer() + "/" + escape_pointer_token(k),
                  "duplicate key " + in_quotes(k) + "; each key may appear only once in an object");
    }
    pending_ = &object[k];
    pending_token_ = "/" + escape_pointer_token(k);
    return true;
  }

  bool parse_error(std::size_t position, const std::string& last_token,
                   const json::exception& ex) override {
    std::string message;
    if (ex.id == 406) {  // out_of_range.406: number overflow
      message =
          "expected a number within the range of a double (about 1.8e308), found " + last_token;
    } else {
      // "[json.exception.parse_error.101] parse error at line 1, column 9: syntax error ..."
      // -> keep what follows the position, which nlohmann sometimes gets wrong.
      message = ex.what();
      const std::size_t at = message.find("parse error");
      const std::size_t colon = message.find(": ", at == std::string::npos ? 0 : at);
      if (colon != std::string::npos) message = message.substr(colon + 2);
      message = "invalid JSON: " + message;
    }
    return fail(line_and_column(text_, position), message);
  }

 private:
  template <class T>
  json* put(T&& value) {
    if (stack_.empty()) {
      root_ = json(std::forward<T>(value));
      last_token_.clear();
      return &root_;
    }
    json& top = *stack_.back();
    if (top.is_array()) {
      last_token_ = "/" + std::to_string(top.size());
      top.push_back(json(std::forward<T>(value)));
      return &top.back();
    }
    *pending_ = json(std::forward<T>(value));
    last_token_ = pending_token_;
    return pending_;
  }

  bool open(json&& container) {
    if (stack_.size() >= kMaxDepth) {  // scenes nest 4 deep; this keeps recursion bounded
      return fail(current_pointer(), "expected at most " + std::to_string(kMaxDepth) +
                                         " levels of nested arrays and objects, found more");
    }
    json* v = put(std::move(container));
    stack_.push_back(v);
    tokens_.push_back(last_token_);
    return true;
  }

  bool close() {
    stack_.pop_back();
    tokens_.pop_back();
    return true;
  }

  std::string current_pointer() const {
    std::string p;
    for (const std::string& t : tokens_) p += t;
    return p;
  }

  bool fail(std::string place, std::string message) {
    failed_ = true;
    error_place_ = std::move(place);
    error_message_ = std::move(message);
    return false;
  }

  static constexpr std::size_t kMaxDepth = 64;

  const std::string& text_;
  json root_;
  std::vector<json*> stack_;         // open containers, outermost first
  std::vector<std::string> tokens_;  // "/key" or "/index" of each open container
  json* pending_ = nullptr;          // slot for the value after the last key
  std::string pending_token_, last_token_;
  bool failed_ = false;
  std::string error_place_, error_message_;
};

// ---------------------------------------------------------------------------------------------
// Typed, range-checked reads

struct Range {
  double lo, hi;
  bool lo_open = false, hi_open = false;

  bool contains(double v) const {
    return (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi);
  }
  std::string text() const {
    return std::string(lo_open ? "(" : "[") + format_number(lo) + ", " + format_number(hi) +
           (hi_open ? ")" : "]");
  }
};

constexpr Range kAnyRange{-kLarge, kLarge};
constexpr Range kPositive{0.0, kLarge, true, false};
constexpr Range kNonNegative{0.0, kLarge};
constexpr Range kUnit{0.0, 1.0};

// Where a value sits: the file and the JSON pointer inside it.
struct Where {
  const std::string* file;
  std::string pointer;

  Where child(std::string_view key) const {
    return {file, pointer + "/" + escape_pointer_token(key)};
  }
  Where child(std::size_t index) const { return {file, pointer + "/" + std::to_string(index)}; }
  [[noreturn]] void fail(const std::string& message) const {
    throw UserError(*file, pointer, message);
  }
};

float read_number(const json& v, const Where& at, const Range& range) {
  const std::string expected = "expected a number in " + range.text();
  if (!v.is_number()) at.fail(expected + ", found " + describe(v));
  const double d = v.get<double>();
  if (!range.contains(d)) at.fail(expected + ", found " + describe(v));
  const float f = static_cast<float>(d);
  if (!range.contains(f)) {  // e.g. 1e-50 for a positive value: rounds to 0 in a float
    at.fail(expected + ", found " + describe(v) + ", which is " + format_float(f) +
            " in single precision");
  }
  return f;
}

std::uint64_t read_integer(const json& v, const Where& at, std::uint64_t lo, std::uint64_t hi) {
  const std::string expected = "expected an integer in [" + std::to_string(lo) + ", " +
                               std::to_string(hi) + "], found " + describe(v);
  std::uint64_t u = 0;
  if (v.is_number_unsigned()) {
    u = v.get<std::uint64_t>();
  } else if (v.is_number_integer()) {
    const std::int64_t i = v.get<std::int64_t>();
    if (i < 0) at.fail(expected);
    u = static_cast<std::uint64_t>(i);
  } else if (v.is_number_float()) {  // accept 1e6 or 3.0, refuse 2.5
    const double d = v.get<double>();
    if (d != std::floor(d)) at.fail(expected + " (not a whole number)");
    if (d < 0.0 || d > 9007199254740992.0) at.fail(expected);  // beyond 2^53: not exact
    u = static_cast<std::uint64_t>(d);
  } else {
    at.fail(expected);
  }
  if (u < lo || u > hi) at.fail(expected);
  return u;
}

glm::vec3 read_vec3(const json& v, const Where& at, const Range& range) {
  if (!v.is_array() || v.size() != 3) {
    at.fail("expected an array of 3 numbers, each in " + range.text() + ", found " + describe(v));
  }
  glm::vec3 out;
  for (std::size_t i = 0; i < 3; ++i)
    out[static_cast<glm::length_t>(i)] = read_number(v[i], at.child(i), range);
  return out;
}

// A colour in [0, 1]: either a grey level c, meaning (c, c, c), or [r, g, b].
glm::vec3 read_unit_color(const json& v, const Where& at) {
  if (v.is_number()) return glm::vec3(read_number(v, at, kUnit));
  if (v.is_array()) return read_vec3(v, at, kUnit);
  at.fail("expected a grey level in [0, 1] or an array of 3 numbers each in [0, 1], found " +
          describe(v));
}

// Reads the keys of one JSON object into fields whose current values are the defaults.
class ObjectReader {
 public:
  ObjectReader(const json& object, Where where, std::string_view what = "an object")
      : object_(object), where_(std::move(where)) {
    if (!object_.is_object())
      where_.fail("expected " + std::string(what) + ", found " + describe(object_));
  }

  const Where& where() const { return where_; }
  Where at(std::string_view key) const { return where_.child(key); }

  // The value under `key`, or nullptr when absent. Either way `key` becomes a known key.
  const json* find(std::string_view key) {
    known_.push_back(key);
    const auto it = object_.find(key);
    return it == object_.end() ? nullptr : &*it;
  }

  const json& require(std::string_view key, std::string_view what) {
    const json* v = find(key);
    if (v == nullptr)
      where_.fail("missing required key " + in_quotes(key) + ": expected " + std::string(what));
    return *v;
  }

  void number(std::string_view key, const Range& range, float& out) {
    if (const json* v = find(key)) out = read_number(*v, at(key), range);
  }

  template <class Int>
  void integer(std::string_view key, std::uint64_t lo, std::uint64_t hi, Int& out) {
    if (const json* v = find(key)) out = static_cast<Int>(read_integer(*v, at(key), lo, hi));
  }

  void vec3(std::string_view key, const Range& range, glm::vec3& out) {
    if (const json* v = find(key)) out = read_vec3(*v, at(key), range);
  }

  void unit_color(std::string_view key, glm::vec3& out) {
    if (const json* v = find(key)) out = read_unit_color(*v, at(key));
  }

  void string(std::string_view key, std::string& out) {
    if (const json* v = find(key)) {
      if (!v->is_string()) at(key).fail("expected a string, found " + describe(*v));
      out = v->get<std::string>();
    }
  }

  // A nested object: `read(ObjectReader&)` fills fields, then unknown keys are refused.
  template <class F>
  void object(std::string_view key, F&& read) {
    if (const json* v = find(key)) {
      ObjectReader child(*v, at(key));
      read(child);
      child.finish();
    }
  }

  // An array of objects, each read like object().
  template <class F>
  void objects(std::string_view key, std::string_view what, F&& read) {
    const json* v = find(key);
    if (v == nullptr) return;
    const Where array_at = at(key);
    if (!v->is_array()) array_at.fail("expected an array of objects, found " + describe(*v));
    for (std::size_t i = 0; i < v->size(); ++i) {
      ObjectReader child((*v)[i], array_at.child(i), what);
      read(child, i);
      child.finish();
    }
  }

  // Refuses every key that no read asked for.
  void finish() const {
    for (const auto& item : object_.items()) {
      const std::string& key = item.key();
      if (std::find(known_.begin(), known_.end(), std::string_view(key)) != known_.end()) continue;
      at(key).fail("unknown key " + in_quotes(key) + suggest(key, known_));
    }
  }

 private:
  const json& object_;
  Where where_;
  std::vector<std::string_view> known_;
};

// ---------------------------------------------------------------------------------------------
// The scene

double length(const glm::vec3& v) {
  const double x = v.x, y = v.y, z = v.z;
  return std::sqrt(x * x + y * y + z * z);
}

constexpr double kMinLength = 1e-6;  // shortest usable direction / camera-to-target distance

void require_nonzero(const glm::vec3& v, const Where& at, std::string_view what) {
  if (length(v) < kMinLength) {
    at.fail("expected a non-zero " + std::string(what) + " (length at least 1e-6), found " +
            format_vec3(v));
  }
}

// A string that must be one of `names`; returns its index.
std::size_t read_choice(ObjectReader& r, std::string_view key,
                        const std::vector<std::string_view>& names, std::size_t fallback) {
  const json* v = r.find(key);
  if (v == nullptr) return fallback;
  if (!v->is_string())
    r.at(key).fail("expected one of " + quoted_list(names) + ", found " + describe(*v));
  const std::string name = v->get<std::string>();
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return i;
  std::string message = "unknown value " + in_quotes(name) + "; expected one of " + quoted_list(names);
  const std::string hint = suggest(name, names);
  if (hint.rfind("; did you mean", 0) == 0) message += hint;
  r.at(key).fail(message);
  return fallback;
}

// read_choice over E's names (engine/core/enum_names.h): the value named at `key`, `fallback`
// when the key is absent.
template <class E>
E read_enum(ObjectReader& r, std::string_view key, E fallback) {
  return enum_table<E>()[read_choice(r, key, enum_name_views<E>(), enum_index(fallback))].value;
}

void read_camera(ObjectReader& r, CameraDescription& c) {
  r.vec3("position", kAnyRange, c.position);
  r.vec3("target", kAnyRange, c.target);
  r.vec3("up", kAnyRange, c.up);
  r.number("fov_y_deg", Range{0.0, 180.0, true, true}, c.fov_y_deg);
  r.number("near", kPositive, c.near);
  r.number("far", kPositive, c.far);
  r.number("orbit_deg_per_second", kAnyRange, c.orbit_deg_per_second);
  r.object("stereo", [&](ObjectReader& st) {
    st.number("interocular", kNonNegative, c.interocular);
    st.number("zero_parallax_distance", kPositive, c.zero_parallax_distance);
    const EyeOrder order = c.swap_eyes ? EyeOrder::right_left : EyeOrder::left_right;
    c.swap_eyes = read_enum(st, "eye_order", order) == EyeOrder::right_left;
  });

  if (!(c.far > c.near)) {
    r.at("far").fail("expected \"far\" greater than \"near\" (" + format_float(c.near) +
                     "), found " + format_float(c.far));
  }
  const glm::vec3 view = c.target - c.position;
  if (length(view) < kMinLength) {
    r.at("target").fail("expected a target different from the camera position " +
                        format_vec3(c.position) + ", found " + format_vec3(c.target));
  }
  require_nonzero(c.up, r.at("up"), "up vector");
  const double u = length(c.up), d = length(view);
  const double ux = c.up.x / u, uy = c.up.y / u, uz = c.up.z / u;
  const double dx = view.x / d, dy = view.y / d, dz = view.z / d;
  const double sine = std::sqrt((uy * dz - uz * dy) * (uy * dz - uz * dy) +
                                (uz * dx - ux * dz) * (uz * dx - ux * dz) +
                                (ux * dy - uy * dx) * (ux * dy - uy * dx));
  if (sine < 1e-3) {
    r.at("up").fail("expected an up vector not parallel to the view direction " +
                    format_vec3(view) + " (from position to target), found " + format_vec3(c.up));
  }
}

// "light": one directional light and the ambient light, the short form.
void read_light(ObjectReader& r, SceneDescription& s) {
  DirectionalLight sun;
  AmbientLight sky;
  r.vec3("direction", kAnyRange, sun.direction);
  r.vec3("color", kNonNegative, sun.color);
  r.vec3("ambient", kNonNegative, sky.color);
  require_nonzero(sun.direction, r.at("direction"), "light direction");
  s.directional_lights = {sun};
  s.light_keyframes = std::vector<LightKeyframes>(1);
  s.ambient_lights = {sky};
}

// One entry of "lights": {"type": "directional", "direction", "color", "intensity"} or
// {"type": "ambient", "color"}.
void read_light_source(ObjectReader& r, SceneDescription& s) {
  const std::vector<std::string_view> types = {"directional", "ambient"};
  r.require("type", "the light type, one of " + quoted_list(types));
  if (read_choice(r, "type", types, 0) == 1) {
    r.vec3("color", kNonNegative, s.ambient_lights.emplace_back().color);
    return;
  }
  DirectionalLight& sun = s.directional_lights.emplace_back();
  LightKeyframes& keys = s.light_keyframes.emplace_back();
  r.vec3("direction", kAnyRange, sun.direction);
  r.vec3("color", kNonNegative, sun.color);
  r.number("intensity", kNonNegative, sun.intensity);
  require_nonzero(sun.direction, r.at("direction"), "light direction");
  // "keys": the light over time; the light's own values are each key's defaults.
  r.objects("keys", "an object {\"time\": seconds, \"direction\", \"color\", \"intensity\"}",
            [&](ObjectReader& k, std::size_t) {
              LightKeyframe key{0.0f, sun.direction, sun.color, sun.intensity};
              k.require("time", "the key's time in seconds, >= 0");
              k.number("time", kNonNegative, key.time);
              k.vec3("direction", kAnyRange, key.direction);
              k.vec3("color", kNonNegative, key.color);
              k.number("intensity", kNonNegative, key.intensity);
              require_nonzero(key.direction, k.at("direction"), "light direction");
              if (!keys.keys.empty() && !(key.time > keys.keys.back().time))
                k.at("time").fail("expected times in increasing order, found " + format_float(key.time) +
                                  " after " + format_float(keys.keys.back().time));
              keys.keys.push_back(key);
            });
  // Until the light phase animates it (and for what reads the scene's lights once, such as the
  // importer): the first key.
  if (!keys.keys.empty()) sun = {keys.keys.front().direction, keys.keys.front().color, keys.keys.front().intensity};
}

// "scattering": {"anisotropy", "octaves", "attenuation", "contribution", "eccentricity"}.
void read_scattering(ObjectReader& r, SunScattering& s) {
  float g = float(s.anisotropy), a = float(s.octaves.attenuation), b = float(s.octaves.contribution),
        c = float(s.octaves.eccentricity);
  r.number("anisotropy", Range{-0.99, 0.99}, g);
  r.integer("octaves", 1, 16, s.octaves.octaves);
  r.number("attenuation", Range{0.0, 1.0, true, false}, a);
  r.number("contribution", kUnit, b);
  r.number("eccentricity", kUnit, c);
  s.anisotropy = g;
  s.octaves.attenuation = a;
  s.octaves.contribution = b;
  s.octaves.eccentricity = c;
}

// "shadows": lit media, {"method": "rays" | "map" | "none", "map_size", "map_slices",
// "fire_lights", "scattering"}.
void read_shadows(ObjectReader& r, ShadowSettings& s) {
  s.method = read_enum(r, "method", s.method);
  r.integer("map_size", 4, 2048, s.map_size);
  r.integer("map_slices", 4, 1024, s.map_slices);
  r.integer("fire_lights", 0, kMaxFireLights, s.fire_lights);
  r.object("scattering", [&](ObjectReader& sc) { read_scattering(sc, s.scattering); });
}

void read_cloud(ObjectReader& r, CloudDescription& c) {
  r.string("name", c.name);
  c.count = static_cast<std::uint32_t>(
      read_integer(r.require("count", "the number of particles, an integer in [1, 10000000]"),
                   r.at("count"), 1, 10'000'000));
  r.number("radius", kPositive, c.radius);
  r.number("density", kUnit, c.density);
  r.unit_color("color", c.color);
  r.object("box", [&](ObjectReader& box) {
    box.vec3("min", kAnyRange, c.box_min);
    box.vec3("max", kAnyRange, c.box_max);
  });
  r.integer("seed", 0, std::numeric_limits<std::uint64_t>::max(), c.seed);
  r.vec3("drift", kAnyRange, c.drift);
  r.number("jitter", kNonNegative, c.jitter);

  static constexpr const char* kAxis[] = {"x", "y", "z"};
  for (glm::length_t i = 0; i < 3; ++i) {
    if (!(c.box_min[i] < c.box_max[i])) {
      r.at("box").fail(std::string("expected \"min\" < \"max\" on every axis, found min.") +
                       kAxis[i] + " = " + format_float(c.box_min[i]) + " >= max." + kAxis[i] +
                       " = " + format_float(c.box_max[i]));
    }
  }
}

void read_mesh(ObjectReader& r, MeshDescription& m) {
  const std::vector<std::string_view> names = enum_name_views<MeshKind>();
  const json& type = r.require("type", "the mesh type, one of " + quoted_list(names));
  if (!type.is_string())
    r.at("type").fail("expected a mesh type, one of " + quoted_list(names) + ", found " +
                      describe(type));
  const std::string name = type.get<std::string>();
  const std::optional<MeshKind> kind = enum_from_name<MeshKind>(name);
  if (!kind) {
    std::string message =
        "unknown mesh type " + in_quotes(name) + "; expected one of " + quoted_list(names);
    const std::string hint = suggest(name, names);
    if (hint.rfind("; did you mean", 0) == 0) message += hint;
    r.at("type").fail(message);
  }
  m.kind = *kind;
  r.vec3("position", kAnyRange, m.position);
  r.number("scale", kPositive, m.scale);
  r.vec3("color", kUnit, m.color);
}

void read_render(ObjectReader& r, RenderDescription& d) {
  d.billboards = read_enum(r, "billboards", d.billboards);
  d.particles = read_enum(r, "particles", d.particles);
  d.shading = read_enum(r, "shading", d.shading);
  d.sort_device = read_enum(r, "sort_device", d.sort_device);
  if (d.shading == ParticleShading::explosion && d.particles == ParticleShape::gaussian)
    r.at("shading").fail("\"explosion\" shading needs \"particles\": \"spherical\" or \"planar\"");
  r.number("layer_scale", Range{0.0, 1.0, true, false}, d.layer_scale);
  if (d.layer_scale != 1.0f && d.layer_scale != 0.5f && d.layer_scale != 0.25f &&
      d.layer_scale != 0.125f) {
    r.at("layer_scale").fail("expected one of 1, 0.5, 0.25, 0.125, found " + format_float(d.layer_scale));
  }
  r.number("motion_blur", Range{0.0, 0.95}, d.motion_blur);
  r.object("fire", [&](ObjectReader& f) {
    f.number("t_min", kPositive, d.fire_t_min);
    f.number("t_max", kPositive, d.fire_t_max);
    f.number("emission", kNonNegative, d.fire_emission);
    f.number("detail_range", kNonNegative, d.fire_detail_range);
    if (!(d.fire_t_max > d.fire_t_min))
      f.at("t_max").fail("expected \"t_max\" greater than \"t_min\" (" + format_float(d.fire_t_min) +
                         " K), found " + format_float(d.fire_t_max));
  });
}

// Volume files: a path ending in .vdb or .pyrop (any case).
bool ends_with_ci(std::string_view s, std::string_view suffix) {
  if (s.size() < suffix.size()) return false;
  for (std::size_t i = 0; i < suffix.size(); ++i) {
    char c = s[s.size() - suffix.size() + i];
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    if (c != suffix[i]) return false;
  }
  return true;
}

std::string read_volume_path(ObjectReader& r, std::string_view key, const json& v,
                             VolumeFileKind& kind) {
  const std::string expected =
      "expected the path of a volume file ending in \".vdb\" (OpenVDB) or \".pyrop\" (particles), "
      "or of a folder ending in \".pyroseq\" (a particle sequence), relative to the scene file's folder";
  if (!v.is_string() || v.get<std::string>().empty())
    r.at(key).fail(expected + ", found " + describe(v));
  const std::string path = v.get<std::string>();
  if (ends_with_ci(path, ".vdb"))
    kind = VolumeFileKind::vdb;
  else if (ends_with_ci(path, ".pyrop"))
    kind = VolumeFileKind::particles;
  else if (ends_with_ci(path, ".pyroseq") || ends_with_ci(path, ".pyroseq/"))
    kind = VolumeFileKind::sequence;
  else
    r.at(key).fail(expected + ", found " + describe(v));
  return path;
}

// `relative` against the scene file's folder (absolute paths stay as they are).
std::string resolve_against(const std::string& scene_file, const std::string& relative) {
  namespace fs = std::filesystem;
  const fs::path p(relative);
  if (p.is_absolute()) return p.lexically_normal().string();
  return (fs::path(scene_file).parent_path() / p).lexically_normal().string();
}

// A volume file that can be read: a regular file, or for a particle sequence a folder holding
// its manifest (engine/io/particle_sequence.h).
bool is_volume_present(const std::string& path, VolumeFileKind kind) {
  std::error_code ec;
  if (kind == VolumeFileKind::sequence)
    return std::filesystem::is_regular_file(std::filesystem::path(path) / "sequence.json", ec);
  return std::filesystem::is_regular_file(path, ec);
}

// A particle sequence's playback keys, refused on any other volume.
void read_sequence_playback(ObjectReader& r, bool any_sequence, SequencePlayback& p) {
  for (std::string_view key : {"start_frame", "loop", "speed"})
    if (!any_sequence && r.find(key) != nullptr)
      r.at(key).fail("unexpected key " + in_quotes(key) + ": it applies to particle sequences (.pyroseq folders)");
  if (r.find("start_frame") != nullptr) {
    r.integer("start_frame", 0, 1'000'000'000, p.start_frame);
    p.has_start_frame = true;
  }
  if (const json* v = r.find("loop")) {
    if (!v->is_boolean()) r.at("loop").fail("expected true or false, found " + describe(*v));
    p.loop = v->get<bool>();
  }
  r.number("speed", Range{0.0, 1000.0, true, false}, p.speed);
}

// volumes[].emission.temperature.table: [[value, kelvin], ...], at least two, values ascending.
std::vector<std::array<float, 2>> read_temperature_table(const json& v, const Where& at) {
  const std::string expected = "expected an array of 2 to 1024 [value, kelvin] pairs, values strictly ascending";
  if (!v.is_array() || v.size() < 2 || v.size() > 1024) at.fail(expected + ", found " + describe(v));
  std::vector<std::array<float, 2>> table;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Where entry = at.child(std::to_string(i));
    if (!v[i].is_array() || v[i].size() != 2) entry.fail(expected + "; this entry is " + describe(v[i]));
    table.push_back({read_number(v[i][0], entry.child("0"), kAnyRange),
                     read_number(v[i][1], entry.child("1"), Range{0.0, 1e6})});
    if (i > 0 && !(table[i][0] > table[i - 1][0]))
      entry.child("0").fail(expected + "; " + format_float(table[i][0]) + " follows " + format_float(table[i - 1][0]));
  }
  return table;
}

// volumes[].emission: {"temperature": {"scale", "offset"} or {"table"}, "intensity"}.
void read_volume_emission(ObjectReader& r, VolumeEmissionDescription& e) {
  r.object("temperature", [&](ObjectReader& t) {
    e.automatic = false;
    if (const json* table = t.find("table")) {
      if (t.find("scale") != nullptr || t.find("offset") != nullptr)
        t.at("table").fail("expected either \"table\" or \"scale\" and \"offset\", found both");
      e.table = read_temperature_table(*table, t.at("table"));
      return;
    }
    if (t.find("scale") == nullptr && t.find("offset") == nullptr)
      t.where().fail("expected \"scale\" and \"offset\" (kelvin = scale value + offset) or \"table\", found neither");
    t.number("scale", Range{-1e6, 1e6}, e.scale);
    t.number("offset", Range{-1e6, 1e6}, e.offset);
  });
  r.number("intensity", Range{0.0, 1e6}, e.intensity);
}

void read_volume(ObjectReader& r, VolumeDescription& v, const std::string& scene_file) {
  v.pointer = r.where().pointer;
  r.string("name", v.name);
  VolumeFileKind file_kind = VolumeFileKind::vdb, fallback_kind = VolumeFileKind::vdb;
  v.file = read_volume_path(
      r, "file",
      r.require("file", "the path of a volume file (.vdb or .pyrop), relative to the scene file's folder"),
      file_kind);
  bool has_fallback = false;
  if (const json* f = r.find("fallback")) {
    v.fallback = read_volume_path(r, "fallback", *f, fallback_kind);
    has_fallback = true;
  }
  const bool any_vdb = file_kind == VolumeFileKind::vdb ||
                       (has_fallback && fallback_kind == VolumeFileKind::vdb);
  // Keys that only mean something for an OpenVDB file.
  const auto vdb_only = [&](std::string_view key) {
    if (!any_vdb && r.find(key) != nullptr) {
      r.at(key).fail("unexpected key " + in_quotes(key) + ": it applies to OpenVDB (.vdb) volumes, "
                     "and " + in_quotes(v.file) + (has_fallback ? " and its fallback are" : " is") +
                     " not: " + (file_kind == VolumeFileKind::sequence ? "a particle sequence (.pyroseq), imported already"
                                                                       : "a particle file (.pyrop)"));
    }
  };
  for (std::string_view key : {"grid", "grid_index", "error", "extinction", "temperature_grid"}) vdb_only(key);
  read_sequence_playback(r, file_kind == VolumeFileKind::sequence || (has_fallback && fallback_kind == VolumeFileKind::sequence),
                         v.sequence);
  r.string("grid", v.grid);
  r.string("temperature_grid", v.temperature_grid);
  r.object("emission", [&](ObjectReader& e) { read_volume_emission(e, v.emission); });
  if (r.find("grid_index") != nullptr) {
    r.integer("grid_index", 0, 1'000'000, v.grid_index);
    if (r.find("grid") != nullptr)
      r.at("grid_index").fail("expected either \"grid\" or \"grid_index\", found both");
  }
  r.number("error", Range{0.0, 1.0, true, false}, v.error);
  r.number("extinction", kPositive, v.extinction);
  v.anchor_center = read_choice(r, "anchor", {"center", "origin"}, 0) == 0;
  r.vec3("position", kAnyRange, v.position);
  r.number("scale", kPositive, v.scale);
  if (r.find("size") != nullptr) {
    r.number("size", kPositive, v.size);
    if (r.find("scale") != nullptr)
      r.at("size").fail("expected either \"scale\" or \"size\", found both");
  }

  // The file, else the fallback: the first that exists.
  const std::string file_path = resolve_against(scene_file, v.file);
  if (is_volume_present(file_path, file_kind)) {
    v.path = file_path;
    v.kind = file_kind;
  } else if (has_fallback) {
    const std::string fallback_path = resolve_against(scene_file, v.fallback);
    if (!is_volume_present(fallback_path, fallback_kind)) {
      r.at("file").fail("expected an existing volume file, found neither one at " + in_quotes(file_path) +
                        " (" + non_regular_file_kind(file_path) + " there) nor at its fallback " +
                        in_quotes(fallback_path) + " (" + non_regular_file_kind(fallback_path) +
                        " there; paths are relative to the scene file's folder)");
    }
    v.path = fallback_path;
    v.kind = fallback_kind;
    v.used_fallback = true;
  } else if (file_kind == VolumeFileKind::sequence) {
    r.at("file").fail("expected a particle sequence folder holding \"sequence.json\" (made by pyro import-vdb), "
                      "found " + (std::filesystem::is_directory(file_path) ? std::string("a folder without it")
                                                                            : non_regular_file_kind(file_path)) +
                      " at " + in_quotes(file_path) + " (paths are relative to the scene file's folder)");
  } else {
    r.at("file").fail("expected an existing volume file, found " + non_regular_file_kind(file_path) +
                      " at " + in_quotes(file_path) + " (paths are relative to the scene file's folder)");
  }
}

// ---------------------------------------------------------------------------------------------
// Flipbook fires (Rose 2007, chapter 4)

// A non-empty array of numbers in `range` (at most `max_size`).
std::vector<float> read_number_array(const json& v, const Where& at, const Range& range,
                                     std::size_t max_size) {
  if (!v.is_array() || v.empty() || v.size() > max_size) {
    at.fail("expected an array of 1 to " + std::to_string(max_size) + " numbers, each in " +
            range.text() + ", found " + describe(v));
  }
  std::vector<float> out;
  for (std::size_t i = 0; i < v.size(); ++i) out.push_back(read_number(v[i], at.child(i), range));
  return out;
}

// A non-empty array of integers (either sign) in [-limit, limit].
std::vector<int> read_signed_array(const json& v, const Where& at, int limit, std::size_t max_size) {
  const std::string expected = "expected an array of 1 to " + std::to_string(max_size) +
                               " integers, each in [" + std::to_string(-limit) + ", " +
                               std::to_string(limit) + "], found ";
  if (!v.is_array() || v.empty() || v.size() > max_size) at.fail(expected + describe(v));
  std::vector<int> out;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const json& e = v[i];
    const double d = e.is_number() ? e.get<double>() : 0.5;
    if (!e.is_number() || d != std::floor(d) || std::fabs(d) > limit)
      at.child(i).fail("expected an integer in [" + std::to_string(-limit) + ", " +
                       std::to_string(limit) + "], found " + describe(e));
    out.push_back(static_cast<int>(d));
  }
  return out;
}

void read_flipbook_group(ObjectReader& r, FlipbookGroup& g) {
  if (const json* v = r.find("offset")) {
    if (!v->is_array() || v->size() != 2)
      r.at("offset").fail("expected [lateral, depth], 2 numbers, found " + describe(*v));
    g.offset = glm::vec2(read_number((*v)[0], r.at("offset").child(std::size_t{0}), kAnyRange),
                         read_number((*v)[1], r.at("offset").child(std::size_t{1}), kAnyRange));
  }
  r.integer("rows", 1, 1000, g.rows);
  r.integer("columns", 1, 1000, g.columns);
  r.number("overlap", Range{0.0, 1.0, false, true}, g.overlap);
  r.number("row_spacing", kNonNegative, g.row_spacing);
  if (const json* v = r.find("column_depths"))
    g.column_depths = read_number_array(*v, r.at("column_depths"), kAnyRange, 1000);
  if (const json* v = r.find("start_frames"))
    g.start_frames = read_signed_array(*v, r.at("start_frames"), 1'000'000, 1000);
  if (const json* v = r.find("row_start_step"))
    g.row_start_step = read_signed_array(json::array({*v}), r.at("row_start_step"), 1'000'000, 1)[0];
  if (const json* v = r.find("increments"))
    g.increments = read_signed_array(*v, r.at("increments"), 1'000'000, 1000);

}

void read_fire(ObjectReader& r, FlipbookFire& f, const std::string& scene_file) {
  r.string("name", f.name);
  r.vec3("position", kAnyRange, f.position);
  r.vec3("up", kAnyRange, f.up);
  require_nonzero(f.up, r.at("up"), "up vector (the normal of the fire's base)");
  r.number("width", kPositive, f.width);
  r.number("aspect", kPositive, f.aspect);
  r.number("intensity", kNonNegative, f.intensity);
  r.number("overlap_exponent", Range{0.0, 4.0}, f.overlap_exponent);
  f.blend = read_enum(r, "blend", f.blend);
  r.number("frames_per_second", kPositive, f.frames_per_second);
  if (r.find("flipbook") != nullptr) {
    std::string folder;
    r.string("flipbook", folder);
    f.flipbook = resolve_against(scene_file, folder);
    std::error_code ec;
    if (!std::filesystem::is_directory(f.flipbook, ec)) {
      r.at("flipbook").fail("expected a folder of PNG flame frames, found no folder at " +
                            in_quotes(f.flipbook) + " (paths are relative to the scene file's folder)");
    }
  }
  r.object("preparation", [&](ObjectReader& p) {
    if (const json* v = p.find("crop")) {
      const std::vector<float> c = read_number_array(*v, p.at("crop"), kUnit, 4);
      if (c.size() != 4 || !(c[2] > c[0]) || !(c[3] > c[1]))
        p.at("crop").fail("expected [x0, y0, x1, y1] as fractions of the frame with x0 < x1 and "
                          "y0 < y1, found " + describe(*v));
      f.preparation.crop = glm::vec4(c[0], c[1], c[2], c[3]);
    }
    p.number("base_line", Range{0.0, 1.0, false, true}, f.preparation.base_line);
    p.number("soften", Range{0.0, 1.0}, f.preparation.soften);
    if (f.preparation.base_line + f.preparation.soften > 1.0f)
      p.at("soften").fail("expected base_line + soften at most 1, found " +
                          format_float(f.preparation.base_line + f.preparation.soften));
  });
  if (const json* groups = r.find("groups")) {
    if (!groups->is_array() || groups->empty())
      r.at("groups").fail("expected a non-empty array of billboard groups, found " + describe(*groups));
    r.objects("groups", "an object describing a group of billboards",
              [&](ObjectReader& g, std::size_t) { read_flipbook_group(g, f.groups.emplace_back()); });
  } else {
    f.groups.emplace_back();  // the thesis' three overlapped pairs
  }
  std::uint64_t billboards = 0;
  for (const FlipbookGroup& g : f.groups)
    billboards += static_cast<std::uint64_t>(g.rows) * static_cast<std::uint64_t>(g.columns);
  if (billboards > 10'000) {
    r.at("groups").fail("expected at most 10000 billboards in a fire (the sum of rows x columns), "
                        "found " + std::to_string(billboards));
  }
}

// ---------------------------------------------------------------------------------------------
// Explosion emitters

bool read_bool(const json& v, const Where& at) {
  if (!v.is_boolean()) at.fail("expected true or false, found " + describe(v));
  return v.get<bool>();
}

// A number (constant), {"min", "max"} (uniform) or {"mean", "stddev"[, "min", "max"]} (normal,
// clamped to [min, max], by default mean ± 3 stddev).
Distribution read_distribution(const json& v, const Where& at, const Range& range) {
  if (v.is_number()) return Distribution::constant(read_number(v, at, range));
  ObjectReader r(v, at,
                 "a number, {\"min\": a, \"max\": b} (uniform) or {\"mean\": m, \"stddev\": s} (normal)");
  Distribution d;
  const json* mean = r.find("mean");
  const json* stddev = r.find("stddev");
  const json* lo = r.find("min");
  const json* hi = r.find("max");
  r.finish();
  if (mean || stddev) {
    if (!mean || !stddev)
      at.fail("expected both \"mean\" and \"stddev\" for a normal distribution");
    const float m = read_number(*mean, at.child("mean"), range);
    const float sd = read_number(*stddev, at.child("stddev"), kNonNegative);
    const float a = lo ? read_number(*lo, at.child("min"), range) : std::max<float>(m - 3 * sd, range.lo);
    const float b = hi ? read_number(*hi, at.child("max"), range) : std::min<float>(m + 3 * sd, range.hi);
    if (!(a <= m && m <= b))
      at.fail("expected min <= mean <= max, found " + format_float(a) + ", " + format_float(m) + ", " +
              format_float(b));
    return Distribution::normal(m, sd, a, b);
  }
  if (!lo || !hi) at.fail("expected \"min\" and \"max\" (uniform) or \"mean\" and \"stddev\" (normal)");
  const float a = read_number(*lo, at.child("min"), range), b = read_number(*hi, at.child("max"), range);
  if (!(a <= b)) at.fail("expected min <= max, found " + format_float(a) + " > " + format_float(b));
  return Distribution::uniform(a, b);
}

// [[t, value], ...] with t in [0, 1] increasing; value a number or [r, g, b].
LifeCurve read_curve(const json& v, const Where& at, const Range& range, bool color) {
  const std::string what = color ? "[t, [r, g, b]]" : "[t, value]";
  if (!v.is_array() || v.empty())
    at.fail("expected a non-empty array of keys " + what + " with t in [0, 1] increasing, found " + describe(v));
  LifeCurve c;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Where k = at.child(i);
    if (!v[i].is_array() || v[i].size() != 2) k.fail("expected a key " + what + ", found " + describe(v[i]));
    CurveKey key;
    key.t = read_number(v[i][0], k.child(std::size_t{0}), kUnit);
    key.value = color ? read_vec3(v[i][1], k.child(1), range) : glm::vec3(read_number(v[i][1], k.child(1), range));
    if (!c.keys.empty() && !(key.t > c.keys.back().t))
      k.child(std::size_t{0}).fail("expected t greater than the previous key's " + format_float(c.keys.back().t) +
                                   ", found " + format_float(key.t));
    c.keys.push_back(key);
  }
  return c;
}

void read_dynamics(ObjectReader& r, ParticleDynamics& d) {
  r.number("gravity_scale", kAnyRange, d.gravity_scale);
  r.number("buoyancy", kAnyRange, d.buoyancy);
  r.number("drag", kNonNegative, d.drag);
  r.number("turbulence", kNonNegative, d.turbulence);
  r.number("turbulence_frequency", kPositive, d.turbulence_frequency);
  r.number("turbulence_speed", kAnyRange, d.turbulence_speed);
  r.integer("turbulence_seed", 0, std::numeric_limits<std::uint64_t>::max(), d.turbulence_seed);
  r.number("cooling", kNonNegative, d.cooling);
  r.number("smoke_below", kNonNegative, d.smoke_below);
  if (const json* v = r.find("collide")) d.collide = read_bool(*v, r.at("collide"));
  r.number("restitution", kUnit, d.restitution);
  r.number("friction", kUnit, d.friction);
  r.object("curves", [&](ObjectReader& c) {
    if (const json* v = c.find("size")) d.size = read_curve(*v, c.at("size"), kNonNegative, false);
    if (const json* v = c.find("opacity")) d.opacity = read_curve(*v, c.at("opacity"), kUnit, false);
    if (const json* v = c.find("temperature"))
      d.temperature = read_curve(*v, c.at("temperature"), kNonNegative, false);
    if (const json* v = c.find("color")) d.color = read_curve(*v, c.at("color"), kNonNegative, true);
  });
}

void read_emitter(ObjectReader& r, EmitterDescription& out) {
  Emitter& e = out.emitter;
  r.string("name", e.name);
  e.medium = read_enum(r, "medium", e.medium);
  r.object("shape", [&](ObjectReader& s) {
    e.shape = read_enum(s, "type", e.shape);
    s.vec3("position", kAnyRange, e.position);
    s.number("radius", kNonNegative, e.radius);
    if (const json* v = s.find("surface")) e.surface = read_bool(*v, s.at("surface"));
    s.vec3("half_extent", kNonNegative, e.half_extent);
    s.vec3("axis", kAnyRange, e.axis);
    require_nonzero(e.axis, s.at("axis"), "disc axis");
  });
  r.number("rate", kNonNegative, e.rate);
  r.number("start", kNonNegative, e.start);
  r.number("duration", kNonNegative, e.duration);
  r.objects("bursts", "an object {\"time\": seconds, \"count\": n}", [&](ObjectReader& b, std::size_t) {
    EmitterBurst burst;
    b.number("time", kNonNegative, burst.time);
    burst.count = static_cast<std::uint32_t>(
        read_integer(b.require("count", "the number of particles, an integer in [0, 10000000]"), b.at("count"), 0,
                     10'000'000));
    e.bursts.push_back(burst);
  });
  std::stable_sort(e.bursts.begin(), e.bursts.end(),
                   [](const EmitterBurst& a, const EmitterBurst& b) { return a.time < b.time; });
  r.vec3("direction", kAnyRange, e.direction);
  require_nonzero(e.direction, r.at("direction"), "direction");
  r.number("cone_deg", Range{0.0, 180.0}, e.cone_deg);
  if (const json* v = r.find("radial")) e.radial = read_bool(*v, r.at("radial"));
  const std::pair<std::string_view, std::pair<Distribution*, Range>> dists[] = {
      {"speed", {&e.speed, kNonNegative}},       {"size", {&e.size, kPositive}},
      {"lifetime", {&e.lifetime, kPositive}},    {"density", {&e.density, kNonNegative}},
      {"temperature", {&e.temperature, kNonNegative}}};
  for (const auto& [key, target] : dists)
    if (const json* v = r.find(key)) *target.first = read_distribution(*v, r.at(key), target.second);
  r.vec3("color", kNonNegative, e.color);
  r.integer("budget", 1, 10'000'000, e.budget);
  r.integer("seed", 0, std::numeric_limits<std::uint64_t>::max(), e.seed);
  r.object("dynamics", [&](ObjectReader& d) { read_dynamics(d, out.dynamics); });
}

void read_environment(ObjectReader& r, SimulationEnvironment& env, float& prewarm) {
  r.vec3("gravity", kAnyRange, env.gravity);
  r.vec3("wind", kAnyRange, env.wind);
  r.number("ambient_temperature", kPositive, env.ambient_temperature);
  r.object("ground", [&](ObjectReader& g) {
    env.ground = true;
    g.number("height", kAnyRange, env.ground_height);
  });
  r.objects("spheres", "an object {\"center\": [x, y, z], \"radius\": r}", [&](ObjectReader& s, std::size_t) {
    SphereCollider c;
    s.vec3("center", kAnyRange, c.center);
    s.number("radius", kPositive, c.radius);
    env.spheres.push_back(c);
  });
  r.objects("boxes", "an object {\"min\": [x, y, z], \"max\": [x, y, z]}", [&](ObjectReader& b, std::size_t) {
    BoxCollider c;
    b.vec3("min", kAnyRange, c.min);
    b.vec3("max", kAnyRange, c.max);
    for (glm::length_t i = 0; i < 3; ++i)
      if (!(c.min[i] < c.max[i])) b.at("max").fail("expected \"min\" < \"max\" on every axis");
    env.boxes.push_back(c);
  });
  r.integer("particle_budget", 1, 100'000'000, env.particle_budget);
  r.number("prewarm", Range{0.0, 3600.0}, prewarm);
}

SceneDescription read_scene(ObjectReader& r) {
  SceneDescription s;
  r.string("name", s.name);
  r.integer("seed", 0, std::numeric_limits<std::uint64_t>::max(), s.seed);
  r.object("output", [&](ObjectReader& o) {
    o.integer("width", 1, 8192, s.width);
    o.integer("height", 1, 8192, s.height);
    o.number("fps", kPositive, s.frames_per_second);
  });
  r.vec3("background", kNonNegative, s.background);
  r.object("camera", [&](ObjectReader& c) { read_camera(c, s.camera); });
  r.object("light", [&](ObjectReader& l) { read_light(l, s); });
  r.object("footprint", [&](ObjectReader& f) {
    f.integer("size", 2, 4096, s.footprint.size);
    f.integer("intervals", 1, 100000, s.footprint.intervals);
  });
  r.object("render", [&](ObjectReader& d) { read_render(d, s.render); });
  r.objects("clouds", "an object describing a cloud",
            [&](ObjectReader& c, std::size_t) { read_cloud(c, s.clouds.emplace_back()); });
  r.objects("meshes", "an object describing a mesh",
            [&](ObjectReader& m, std::size_t) { read_mesh(m, s.meshes.emplace_back()); });
  r.objects("volumes", "an object describing a volume", [&](ObjectReader& v, std::size_t) {
    read_volume(v, s.volumes.emplace_back(), *r.where().file);
  });
  r.object("environment", [&](ObjectReader& e) { read_environment(e, s.environment, s.prewarm); });
  r.objects("emitters", "an object describing an emitter",
            [&](ObjectReader& e, std::size_t) { read_emitter(e, s.emitters.emplace_back()); });
  r.objects("fires", "an object describing a flipbook fire", [&](ObjectReader& f, std::size_t) {
    read_fire(f, s.fires.emplace_back(), *r.where().file);
  });
  r.object("budget", [&](ObjectReader& b) {
    b.integer("particles", 1, 4'000'000'000ull, s.budget.particles);
    std::uint64_t memory_mib = s.budget.memory_bytes >> 20;
    b.integer("memory_mib", 1, 1ull << 20, memory_mib);
    s.budget.memory_bytes = memory_mib << 20;
    b.integer("texture_size", 1, 65536, s.budget.texture_size);
  });
  r.object("quality", [&](ObjectReader& q) {
    const json& v = q.require("max_rmse", "a number in (0, 1], the largest image RMSE accepted");
    s.quality.max_rmse = read_number(v, q.at("max_rmse"), Range{0.0, 1.0, true, false});
  });
  r.object("shadows", [&](ObjectReader& sh) { read_shadows(sh, s.shadows.emplace()); });
  if (r.find("lights") != nullptr) {
    if (r.find("light") != nullptr)
      r.at("lights").fail("expected either \"light\" or \"lights\", found both");
    s.directional_lights.clear();
    s.light_keyframes.clear();
    s.ambient_lights.clear();
    r.objects("lights", "an object describing a light",
              [&](ObjectReader& l, std::size_t) { read_light_source(l, s); });
  }
  r.finish();
  return s;
}

}  // namespace

SceneDescription parse_scene(const std::string& text, const std::string& file_name_for_messages) {
  const std::string& file = file_name_for_messages;
  if (text.find_first_not_of(" \t\r\n") == std::string::npos) {
    throw UserError(file, "", "expected a JSON object describing the scene, found an empty file");
  }
  // No scene string (names, paths) is near this long; refused before the parser copies it.
  constexpr std::size_t kMaxStringBytes = 1 << 16;
  if (const auto long_string = find_long_json_string(text, kMaxStringBytes))
    throw UserError(file, line_and_column(text, long_string->offset + 1),
                    "strings of at most " + std::to_string(kMaxStringBytes) +
                        " bytes, found one of " + std::to_string(long_string->bytes) + " bytes");
  JsonDocumentBuilder builder(text);
  json::sax_parse(text, &builder, json::input_format_t::json, /*strict=*/true,
                  /*ignore_comments=*/false);
  if (builder.failed()) throw UserError(file, builder.error_place(), builder.error_message());

  const json& root = builder.root();
  if (!root.is_object()) {
    throw UserError(
        file, "", "expected a JSON object at the top level of the scene, found " + describe(root));
  }
  ObjectReader reader(root, Where{&file, ""});
  SceneDescription scene = read_scene(reader);
  scene.file = file;
  // The scene as parsed, not its bytes: key order, spacing and number spelling do not count.
  scene.content_digest = sha256_hex(root.dump());
  return scene;
}

namespace {

// Everything `fd` holds until its end. Throws UserError naming `path` on a read error.
std::string read_all(int fd, const std::string& path) {
  std::string text;
  char buffer[1 << 16];
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw UserError(path, "", std::string("cannot read scene file: ") + std::strerror(errno));
    if (n == 0) return text;
    text.append(buffer, static_cast<std::size_t>(n));
  }
}

// A file descriptor closed when it goes out of scope.
struct OpenFile {
  int fd = -1;
  ~OpenFile() {
    if (fd >= 0) ::close(fd);
  }
};

// A pipe (bash's <(...), standard input) is read once; a named FIFO that no program writes to
// would block the open and every read forever, so it is opened without blocking and refused when
// nothing arrives within a second.
std::string read_fifo(const std::string& path) {
  const OpenFile file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
  if (file.fd < 0) throw UserError(path, "", std::string("cannot open scene file: ") + std::strerror(errno));
  struct pollfd p {file.fd, POLLIN, 0};
  int ready;
  do ready = ::poll(&p, 1, 1000);
  while (ready < 0 && errno == EINTR);
  if (ready == 0)
    throw UserError(path, "", "expected a scene file, found a FIFO (named pipe) that no program "
                              "wrote to within 1 s");
  ::fcntl(file.fd, F_SETFL, ::fcntl(file.fd, F_GETFL) & ~O_NONBLOCK);
  return read_all(file.fd, path);
}

std::string read_scene_text(const std::string& path) {
  if (path == "-") return read_all(STDIN_FILENO, "<standard input>");
  if (is_fifo(path)) return read_fifo(path);
  const std::string kind = non_regular_file_kind(path);
  if (kind == "no file") throw UserError(path, "", std::string("cannot open scene file: ") + std::strerror(ENOENT));
  if (!kind.empty()) throw UserError(path, "", "expected a scene file, found " + kind);
  const OpenFile file{::open(path.c_str(), O_RDONLY | O_CLOEXEC)};
  if (file.fd < 0) throw UserError(path, "", std::string("cannot open scene file: ") + std::strerror(errno));
  return read_all(file.fd, path);
}

}  // namespace

SceneDescription load_scene(const std::string& path) {
  return parse_scene(read_scene_text(path), path == "-" ? "<standard input>" : path);
}

}  // namespace pyro
