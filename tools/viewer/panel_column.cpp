#include "tools/viewer/panel_column.h"

#include <vector>

namespace pyro {

namespace {

// Between two panels, in pixels.
constexpr float kPanelGap = 2.0f;

}  // namespace

const char* panel_name(ViewerPanel p) {
  static const std::array<const char*, PanelColumn::count> names = {"Status", "Inspector",
                                                                    "Profiler", "Stereo"};
  return names[size_t(p)];
}

PanelColumn::PanelColumn(bool inspector_expanded) {
  (*this)[ViewerPanel::status].expanded = true;
  (*this)[ViewerPanel::inspector].expanded = inspector_expanded;
}

void PanelColumn::expand(const std::string& name) {
  for (size_t i = 0; i < count; ++i) {
    std::string lower = panel_name(ViewerPanel(i));
    lower[0] = char(lower[0] - 'A' + 'a');
    if (lower == name) panels_[i].expanded = true;
  }
}

void PanelColumn::place(const PanelRect& column, const std::array<float, count>& wanted,
                        float header) {
  std::vector<ColumnPanel> stack;
  for (size_t i = 0; i < count; ++i) stack.push_back({header, wanted[i], panels_[i].expanded});
  const std::vector<PanelRect> rects = stack_panels(column, stack, kPanelGap);
  for (size_t i = 0; i < count; ++i) panels_[i].rect = rects[i];
}

nlohmann::json panel_rect_json(const PanelRect& r) {
  return {{"x", r.x}, {"y", r.y}, {"width", r.width}, {"height", r.height}};
}

nlohmann::json PanelColumn::to_json() const {
  nlohmann::json out = nlohmann::json::array();
  for (size_t i = 0; i < count; ++i) {
    nlohmann::json j = panel_rect_json(panels_[i].rect);
    j["name"] = panel_name(ViewerPanel(i));
    j["expanded"] = panels_[i].expanded;
    out.push_back(j);
  }
  return out;
}

}  // namespace pyro
