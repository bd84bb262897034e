#include "tools/viewer/inspector_panel.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "engine/io/json_text_edit.h"
#include "engine/io/parameter_text.h"

namespace pyro {

namespace {

using json = nlohmann::json;

const ImVec4 kErrorColour{1.0f, 0.45f, 0.4f, 1.0f};

// One key being drawn: where it is, what the file holds there (null: absent), and the request
// the panel fills.
struct KeyPlace {
  const json& tree;
  std::vector<std::string> tokens;
  const json& value;
  InspectorRequest& request;
};

// The pointer whose nodes open when they first appear (pyro view --inspect); empty: none.
std::string& focus_pointer() {
  static std::string focus;
  return focus;
}

// Opens the node at `pointer` the first time it is drawn when it lies on the focus's path.
void open_if_focused(const std::string& pointer) {
  const std::string& focus = focus_pointer();
  if (!focus.empty() && (focus == pointer || focus.rfind(pointer + "/", 0) == 0))
    ImGui::SetNextItemOpen(true, ImGuiCond_Once);
}

void ask(const KeyPlace& k, json value, bool coalesce) {
  k.request.edit = edit_creating_parents(k.tree, k.tokens, std::move(value), coalesce);
}

// A drag or slider's change joins the previous step of the same drag, not an earlier one.
bool continuing_drag() { return !ImGui::IsItemActivated(); }

void tooltip(const ParameterKey& key) {
  if (ImGui::IsItemHovered() && !key.description.empty())
    ImGui::SetTooltip("%.*s", int(key.description.size()), key.description.data());
}

const json& shown_value(const ParameterKey& key, const json& value) {
  return value.is_null() ? key.default_value : value;
}

// Sliders for short closed ranges (a fraction, an angle); drags, clamped, for the rest.
bool bounded(const Range& r) { return r.hi - r.lo <= 1e4; }

float drag_speed(float v) { return std::max(0.001f, std::fabs(v) * 0.01f); }

void number_widget(const ParameterKey& key, const KeyPlace& k, const char* label) {
  const json& v = shown_value(key, k.value);
  float f = v.is_number() ? v.get<float>() : 0.0f;
  const bool changed = bounded(key.range)
                           ? ImGui::SliderFloat(label, &f, float(key.range.lo), float(key.range.hi), "%.4g")
                           : ImGui::DragFloat(label, &f, drag_speed(f), float(key.range.lo),
                                              float(key.range.hi), "%.4g");
  if (changed) ask(k, float_json(f), continuing_drag());
}

void integer_widget(const ParameterKey& key, const KeyPlace& k, const char* label) {
  const json& v = shown_value(key, k.value);
  std::uint64_t n = v.is_number_unsigned() || v.is_number_integer() ? v.get<std::uint64_t>() : key.integer_min;
  if (ImGui::DragScalar(label, ImGuiDataType_U64, &n, std::max(1.0f, float(n) * 0.01f),
                        &key.integer_min, &key.integer_max))
    ask(k, n, continuing_drag());
}

glm::vec3 vec3_of(const json& v, float grey_fallback = 0.0f) {
  if (v.is_number()) return glm::vec3(v.get<float>());
  glm::vec3 out(grey_fallback);
  if (v.is_array() && v.size() == 3)
    for (int i = 0; i < 3; ++i) out[i] = v[i].is_number() ? v[i].get<float>() : 0.0f;
  return out;
}

json vec3_json(const float* f) { return json::array({float_json(f[0]), float_json(f[1]), float_json(f[2])}); }

void vec3_widget(const ParameterKey& key, const KeyPlace& k, const char* label, bool colour) {
  const glm::vec3 v = vec3_of(shown_value(key, k.value));
  float f[3] = {v.x, v.y, v.z};
  const bool changed = colour ? ImGui::ColorEdit3(label, f, ImGuiColorEditFlags_Float)
                              : ImGui::DragFloat3(label, f, drag_speed(std::max({std::fabs(f[0]), std::fabs(f[1]), std::fabs(f[2])})),
                                                  float(key.range.lo), float(key.range.hi), "%.4g");
  if (changed) ask(k, vec3_json(f), continuing_drag());
}

void choice_widget(const ParameterKey& key, const KeyPlace& k, const char* label) {
  const json& v = shown_value(key, k.value);
  const std::string current = v.is_string() ? v.get<std::string>() : "";
  // A choice without a default that the file leaves out (its description says what applies).
  if (!ImGui::BeginCombo(label, current.empty() ? "(not set)" : current.c_str())) return;
  for (std::string_view choice : key.choices) {
    const std::string name(choice);
    if (ImGui::Selectable(name.c_str(), name == current) && name != current) ask(k, name, false);
  }
  ImGui::EndCombo();
}

void string_widget(const ParameterKey& key, const KeyPlace& k, const char* label) {
  const json& v = shown_value(key, k.value);
  std::string text = v.is_string() ? v.get<std::string>() : "";
  if (ImGui::InputText(label, &text, ImGuiInputTextFlags_EnterReturnsTrue)) ask(k, text, false);
}

// [[t, value], ...] with t ascending in [0, 1], drawn piecewise linear.
bool is_curve(const json& v) {
  if (!v.is_array() || v.empty()) return false;
  return std::all_of(v.begin(), v.end(), [](const json& p) {
    return p.is_array() && p.size() == 2 && p[0].is_number() && p[1].is_number();
  });
}

std::vector<float> sample_curve(const json& curve, int n) {
  std::vector<float> out(size_t(n), 0.0f);
  for (int i = 0; i < n; ++i) {
    const float t = float(i) / float(n - 1);
    size_t j = 0;
    while (j + 1 < curve.size() && curve[j + 1][0].get<float>() < t) ++j;
    const float t0 = curve[j][0].get<float>(), v0 = curve[j][1].get<float>();
    const size_t k = std::min(j + 1, curve.size() - 1);
    const float t1 = curve[k][0].get<float>(), v1 = curve[k][1].get<float>();
    out[size_t(i)] = t <= t0 || t1 <= t0 ? v0 : t >= t1 ? v1 : v0 + (v1 - v0) * (t - t0) / (t1 - t0);
  }
  return out;
}

// Any other shape (curves, keyframes, tables): its JSON, edited as text; a curve is also plotted.
void json_widget(const ParameterKey& key, const KeyPlace& k, const char* label) {
  const json& v = shown_value(key, k.value);
  if (is_curve(v)) {
    const std::vector<float> samples = sample_curve(v, 64);
    ImGui::PlotLines("##curve", samples.data(), int(samples.size()), 0, nullptr, FLT_MAX, FLT_MAX,
                     ImVec2(0, 40));
  }
  std::string text = v.is_null() ? "" : v.dump();
  if (!ImGui::InputText(label, &text, ImGuiInputTextFlags_EnterReturnsTrue)) return;
  json parsed = json::parse(text, nullptr, false);
  if (parsed.is_discarded()) k.request.error = json_pointer_text(k.tokens) + ": expected JSON, found " + in_quotes(text);
  else ask(k, std::move(parsed), false);
}

void draw_table(const ParameterTable& table, const json& tree, const std::vector<std::string>& at,
                const json& object, InspectorRequest& request, bool present_only);

std::string entry_label(const std::string& key, size_t i, const json& entry) {
  std::string label = key + "[" + std::to_string(i) + "]";
  for (const char* naming : {"name", "type", "medium"})
    if (entry.is_object() && entry.contains(naming) && entry[naming].is_string())
      return label + " " + entry[naming].get<std::string>();
  return label;
}

void objects_widget(const ParameterKey& key, const KeyPlace& k, const std::string& name) {
  const size_t n = k.value.is_array() ? k.value.size() : 0;
  const std::string label = name + " (" + std::to_string(n) + ")";
  open_if_focused(json_pointer_text(k.tokens));
  if (!ImGui::TreeNode(label.c_str())) return;
  for (size_t i = 0; i < n; ++i) {
    ImGui::PushID(int(i));
    std::vector<std::string> at = k.tokens;
    at.push_back(std::to_string(i));
    open_if_focused(json_pointer_text(at));
    if (ImGui::TreeNode(entry_label(name, i, k.value[i]).c_str())) {
      draw_table(*key.table, k.tree, at, k.value[i], k.request, false);
      ImGui::TreePop();
    }
    ImGui::PopID();
  }
  ImGui::TreePop();
}

void draw_key(const ParameterKey& key, const KeyPlace& k) {
  const std::string name(key.name);
  const std::string label = name + "##value";
  const bool absent = k.value.is_null();
  if (absent) ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  switch (key.type) {
    case ParameterType::number: number_widget(key, k, label.c_str()); break;
    case ParameterType::integer: integer_widget(key, k, label.c_str()); break;
    case ParameterType::boolean: {
      const json& v = shown_value(key, k.value);
      bool b = v.is_boolean() && v.get<bool>();
      if (ImGui::Checkbox(label.c_str(), &b)) ask(k, b, false);
      break;
    }
    case ParameterType::string: string_widget(key, k, label.c_str()); break;
    case ParameterType::vec3: vec3_widget(key, k, label.c_str(), false); break;
    case ParameterType::unit_color: vec3_widget(key, k, label.c_str(), true); break;
    case ParameterType::choice: choice_widget(key, k, label.c_str()); break;
    case ParameterType::object:
      open_if_focused(json_pointer_text(k.tokens));
      if (ImGui::TreeNode(name.c_str())) {
        draw_table(*key.table, k.tree, k.tokens, k.value, k.request, false);
        ImGui::TreePop();
      }
      break;
    case ParameterType::objects: objects_widget(key, k, name); break;
    case ParameterType::custom: json_widget(key, k, label.c_str()); break;
  }
  tooltip(key);
  if (absent) ImGui::PopStyleColor();
}

void draw_table(const ParameterTable& table, const json& tree, const std::vector<std::string>& at,
                const json& object, InspectorRequest& request, bool present_only) {
  static const json kAbsent;
  for (const ParameterKey& key : table.keys) {
    const std::string name(key.name);
    const bool present = object.is_object() && object.contains(name);
    if (present_only && !present) continue;
    std::vector<std::string> tokens = at;
    tokens.push_back(name);
    ImGui::PushID(name.c_str());
    draw_key(key, KeyPlace{tree, std::move(tokens), present ? object[name] : kAbsent, request});
    ImGui::PopID();
  }
}

void draw_status(const InspectorStatus& status, InspectorRequest& request, std::string& save_as_path) {
  ImGui::TextUnformatted((status.file + (status.modified ? " (modified)" : "")).c_str());
  ImGui::BeginDisabled(!status.can_undo);
  if (ImGui::Button("Undo")) request.undo = true;
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(!status.can_redo);
  if (ImGui::Button("Redo")) request.redo = true;
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(!status.modified);
  if (ImGui::Button("Save")) request.save = true;
  ImGui::EndDisabled();
  ImGui::InputText("##save_as", &save_as_path);
  ImGui::SameLine();
  if (ImGui::Button("Save as") && !save_as_path.empty()) request.save_as = save_as_path;
  if (!status.error.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, kErrorColour);
    ImGui::TextWrapped("%s", status.error.c_str());
    ImGui::PopStyleColor();
  } else if (!status.message.empty()) {
    ImGui::TextWrapped("%s", status.message.c_str());
  }
}

}  // namespace

void draw_scene_keys(const ParameterTable& table, const json& tree, const std::vector<std::string>& tokens,
                     InspectorRequest& request) {
  const json* object = &tree;
  for (const std::string& t : tokens) {
    static const json kAbsent;
    object = object->is_object() && object->contains(t) ? &(*object)[t] : &kAbsent;
  }
  draw_table(table, tree, tokens, *object, request, false);
}

InspectorRequest InspectorPanel::draw(const json& tree, const ParameterTable& table,
                                      const InspectorStatus& status, DockedPanel& panel) {
  InspectorRequest request;
  focus_pointer() = focus_;
  const DockedPart part = begin_docked_panel("Inspector", panel);
  if (part == DockedPart::body) {
    draw_status(status, request, save_as_path_);
    ImGui::Separator();
    draw_table(table, tree, {}, tree, request, true);
    if (ImGui::TreeNode("Keys the file does not set")) {
      for (const ParameterKey& key : table.keys) {
        if (tree.contains(std::string(key.name))) continue;
        ImGui::PushID(std::string(key.name).c_str());
        draw_key(key, KeyPlace{tree, {std::string(key.name)}, json(), request});
        ImGui::PopID();
      }
      ImGui::TreePop();
    }
  }
  end_docked_panel(part);
  return request;
}

}  // namespace pyro
