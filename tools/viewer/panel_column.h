#pragma once
// The viewer's panels in their column (panel_layout.h), top to bottom: status, inspector,
// profiler, stereo. It holds whether each is expanded — by default the status alone, and the
// inspector too when pyro view --inspect names where it opens — places them every frame, and
// reports where it put them (pyro view --json, "layout").
#include <array>
#include <cstddef>
#include <string>

#include <nlohmann/json.hpp>

#include "tools/viewer/docked_panel.h"
#include "tools/viewer/panel_layout.h"

namespace pyro {

enum class ViewerPanel : size_t { status, inspector, profiler, stereo };

class PanelColumn {
 public:
  static constexpr size_t count = 4;

  explicit PanelColumn(bool inspector_expanded);

  // Places the panels in `column` for this frame: `wanted`, the height each would like expanded
  // (in ViewerPanel's order); `header`, a collapsed panel's height.
  void place(const PanelRect& column, const std::array<float, count>& wanted, float header);

  // Expands the panel of that name (lower case: "status", "inspector", "profiler", "stereo"); any
  // other name, none.
  void expand(const std::string& name);

  DockedPanel& operator[](ViewerPanel p) { return panels_[size_t(p)]; }
  const DockedPanel& operator[](ViewerPanel p) const { return panels_[size_t(p)]; }

  // [{"name", "x", "y", "width", "height", "expanded"}, ...] as last placed, top to bottom.
  nlohmann::json to_json() const;

 private:
  std::array<DockedPanel, count> panels_;
};

// {"x", "y", "width", "height"}.
nlohmann::json panel_rect_json(const PanelRect& r);

// The name each panel's window and header carry.
const char* panel_name(ViewerPanel p);

}  // namespace pyro
