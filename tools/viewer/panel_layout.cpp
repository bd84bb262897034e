#include "tools/viewer/panel_layout.h"

#include <algorithm>
#include <cmath>
#include <numeric>

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

namespace {

// Max-min fair shares of `spare` in whole pixels: from the smallest want up, each gets what it
// wants or an equal share of what is left, whichever is less.
std::vector<float> fair_shares(const std::vector<float>& wants, float spare) {
  std::vector<size_t> order(wants.size());
  std::iota(order.begin(), order.end(), size_t(0));
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return wants[a] < wants[b]; });
  std::vector<float> shares(wants.size(), 0.0f);
  float left = spare;
  for (size_t k = 0; k < order.size(); ++k) {
    shares[order[k]] = std::min(wants[order[k]], std::floor(left / float(order.size() - k)));
    left -= shares[order[k]];
  }
  return shares;
}

}  // namespace

std::vector<PanelRect> stack_panels(const PanelRect& column, const std::vector<ColumnPanel>& panels,
                                    float gap) {
  float headers = 0;
  std::vector<float> bodies;
  for (const ColumnPanel& p : panels) {
    headers += p.header;
    bodies.push_back(p.expanded ? std::max(0.0f, std::floor(p.wanted - p.header)) : 0.0f);
  }
  if (!panels.empty()) headers += gap * float(panels.size() - 1);
  const std::vector<float> shares = fair_shares(bodies, std::max(0.0f, column.height - headers));
  const float bottom = column.y + column.height;
  std::vector<PanelRect> rects;
  float y = column.y;
  for (size_t i = 0; i < panels.size(); ++i) {
    const float top = std::min(y, bottom);
    rects.push_back(
        {column.x, top, column.width, std::min(panels[i].header + shares[i], bottom - top)});
    y = top + rects.back().height + gap;
  }
  return rects;
}

}  // namespace pyro
