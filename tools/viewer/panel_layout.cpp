#include "tools/viewer/panel_layout.h"

#include <algorithm>
#include <cmath>

namespace pyro {

float panel_column_width(float scale) { return std::round(360.0f * scale); }

WindowSize viewer_window_size(int frame_width, int frame_height, float column_width) {
  if (column_width <= 0) return {frame_width, frame_height};
  const int column = int(std::ceil(column_width));
  return {std::max(frame_width, column) + column, std::max(frame_height, 240)};
}

WindowSplit split_window(float window_width, float window_height, float column_width) {
  const float column = std::floor(std::clamp(column_width, 0.0f, window_width / 2));
  const float view_width = window_width - column;
  return {{0, 0, view_width, window_height}, {view_width, 0, column, window_height}};
}

PanelRect fit_frame(const PanelRect& area, int frame_width, int frame_height) {
  if (frame_width <= 0 || frame_height <= 0) return {area.x, area.y, 0, 0};
  const double scale =
      std::min(double(area.width) / frame_width, double(area.height) / frame_height);
  const float w = float(std::floor(frame_width * scale + 0.5)),
              h = float(std::floor(frame_height * scale + 0.5));
  return {area.x + std::floor((area.width - w) / 2), area.y + std::floor((area.height - h) / 2), w,
          h};
}

std::vector<PanelRect> stack_panels(const PanelRect& column, const std::vector<ColumnPanel>& panels,
                                    float gap) {
  float headers = 0, bodies = 0;
  for (const ColumnPanel& p : panels) {
    headers += p.header;
    if (p.expanded) bodies += std::max(0.0f, p.wanted - p.header);
  }
  if (!panels.empty()) headers += gap * float(panels.size() - 1);
  const float spare = std::max(0.0f, column.height - headers);
  const float share = bodies > spare ? spare / bodies : 1.0f;
  const float bottom = column.y + column.height;
  std::vector<PanelRect> rects;
  float y = column.y;
  for (const ColumnPanel& p : panels) {
    const float body = p.expanded ? std::floor(std::max(0.0f, p.wanted - p.header) * share) : 0.0f;
    const float top = std::min(y, bottom);
    rects.push_back({column.x, top, column.width, std::min(p.header + body, bottom - top)});
    y = top + rects.back().height + gap;
  }
  return rects;
}

}  // namespace pyro
