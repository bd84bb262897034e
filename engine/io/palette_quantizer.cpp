#include "engine/io/palette_quantizer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace pyro {

namespace {

constexpr int kCellBits = 6;
constexpr size_t kCacheSlots = size_t{1} << 16;

// A histogram cell as a weighted point: the mean of its colours and how many there were.
struct WeightedColor {
  double c[3];
  double w;
};

// Sums over a set of weighted points, from which the set's mean and its sum of squared errors
// (about that mean) follow: sse = sum w |x|^2 - |sum w x|^2 / sum w.
struct Moments {
  double w = 0.0, s[3] = {0.0, 0.0, 0.0}, q = 0.0;
  void add(const WeightedColor& p) {
    w += p.w;
    for (int k = 0; k < 3; ++k) {
      s[k] += p.w * p.c[k];
      q += p.w * p.c[k] * p.c[k];
    }
  }
  double sse() const {
    if (w <= 0.0) return 0.0;
    return std::max(0.0, q - (s[0] * s[0] + s[1] * s[1] + s[2] * s[2]) / w);
  }
};

Moments moments_of(const std::vector<WeightedColor>& points, const std::vector<uint32_t>& members) {
  Moments m;
  for (uint32_t i : members) m.add(points[i]);
  return m;
}

struct Box {
  std::vector<uint32_t> members;
  double sse = 0.0;
};

struct Split {
  int axis = -1;
  size_t at = 0;  // members [0, at) and [at, n) once sorted along `axis`
  double sse = std::numeric_limits<double>::infinity();
};

// The best cut of `box` along `axis`: members sorted along it, every cut between two distinct
// coordinates tried with prefix moments.
Split best_split_along(const std::vector<WeightedColor>& points, Box& box, int axis) {
  std::vector<uint32_t>& m = box.members;
  std::stable_sort(m.begin(), m.end(),
                   [&](uint32_t a, uint32_t b) { return points[a].c[axis] < points[b].c[axis]; });
  const Moments total = moments_of(points, m);
  Split best;
  best.axis = axis;
  Moments left;
  for (size_t k = 1; k < m.size(); ++k) {
    left.add(points[m[k - 1]]);
    if (points[m[k - 1]].c[axis] == points[m[k]].c[axis]) continue;
    Moments right;
    right.w = total.w - left.w;
    right.q = total.q - left.q;
    for (int c = 0; c < 3; ++c) right.s[c] = total.s[c] - left.s[c];
    const double sse = left.sse() + right.sse();
    if (sse < best.sse) {
      best.sse = sse;
      best.at = k;
    }
  }
  return best;
}

// Splits `box` in two at its best cut over the three channels; false when all its points share
// one colour.
bool split_box(const std::vector<WeightedColor>& points, Box& box, Box& other) {
  Split best;
  for (int axis = 0; axis < 3; ++axis) {
    const Split s = best_split_along(points, box, axis);
    if (s.sse < best.sse) best = s;
  }
  if (best.axis < 0 || best.at == 0) return false;
  best_split_along(points, box, best.axis);  // sorted along the chosen channel again
  other.members.assign(box.members.begin() + static_cast<std::ptrdiff_t>(best.at), box.members.end());
  box.members.resize(best.at);
  box.sse = moments_of(points, box.members).sse();
  other.sse = moments_of(points, other.members).sse();
  return true;
}

// Wu's greedy cut: the box of largest squared error split until there are `colors` boxes (or
// no box can be split).
std::vector<Box> cut_boxes(const std::vector<WeightedColor>& points, int colors) {
  std::vector<Box> boxes(1);
  boxes[0].members.resize(points.size());
  std::iota(boxes[0].members.begin(), boxes[0].members.end(), 0u);
  boxes[0].sse = moments_of(points, boxes[0].members).sse();
  while (static_cast<int>(boxes.size()) < colors) {
    size_t worst = 0;
    for (size_t b = 1; b < boxes.size(); ++b)
      if (boxes[b].sse > boxes[worst].sse) worst = b;
    if (boxes[worst].sse <= 0.0) break;
    Box other;
    if (!split_box(points, boxes[worst], other)) break;
    boxes.push_back(std::move(other));
  }
  return boxes;
}

double distance2(const double* a, const double* b) {
  const double d0 = a[0] - b[0], d1 = a[1] - b[1], d2 = a[2] - b[2];
  return d0 * d0 + d1 * d1 + d2 * d2;
}

// Lloyd's iterations: each point to its nearest centre, each centre to its points' weighted mean
// (a centre that keeps no point stays), until no point changes centre or `rounds` are done.
void refine_centres(const std::vector<WeightedColor>& points, std::vector<WeightedColor>& centres,
                    int rounds) {
  std::vector<uint32_t> owner(points.size(), std::numeric_limits<uint32_t>::max());
  for (int round = 0; round < rounds; ++round) {
    bool changed = false;
    std::vector<Moments> sums(centres.size());
    for (size_t p = 0; p < points.size(); ++p) {
      uint32_t nearest = 0;
      double best = std::numeric_limits<double>::infinity();
      for (size_t c = 0; c < centres.size(); ++c) {
        const double d = distance2(points[p].c, centres[c].c);
        if (d < best) {
          best = d;
          nearest = static_cast<uint32_t>(c);
        }
      }
      changed = changed || owner[p] != nearest;
      owner[p] = nearest;
      sums[nearest].add(points[p]);
    }
    for (size_t c = 0; c < centres.size(); ++c)
      if (sums[c].w > 0.0)
        for (int k = 0; k < 3; ++k) centres[c].c[k] = sums[c].s[k] / sums[c].w;
    if (!changed) return;
  }
}

uint8_t to_byte(double v) { return static_cast<uint8_t>(std::clamp(std::lround(v), 0l, 255l)); }

}  // namespace

PaletteBuilder::PaletteBuilder() : cells_(size_t{1} << (3 * kCellBits)) {}

void PaletteBuilder::add_pixels(const uint8_t* rgb, size_t pixels) {
  constexpr int drop = 8 - kCellBits;
  for (size_t i = 0; i < pixels; ++i) {
    const uint8_t* p = rgb + 3 * i;
    const size_t cell = (size_t(p[0] >> drop) << (2 * kCellBits)) |
                        (size_t(p[1] >> drop) << kCellBits) | size_t(p[2] >> drop);
    Cell& c = cells_[cell];
    c.count += 1;
    for (int k = 0; k < 3; ++k) c.sum[k] += p[k];
  }
}

std::vector<PaletteColor> PaletteBuilder::palette(int colors) const {
  if (colors < 1 || colors > 256) throw std::invalid_argument("PaletteBuilder: 1 to 256 colours");
  std::vector<WeightedColor> points;
  for (const Cell& c : cells_)
    if (c.count > 0) {
      const double n = static_cast<double>(c.count);
      points.push_back({{c.sum[0] / n, c.sum[1] / n, c.sum[2] / n}, n});
    }
  if (points.empty()) return {};
  std::vector<WeightedColor> centres;
  for (const Box& box : cut_boxes(points, colors)) {
    const Moments m = moments_of(points, box.members);
    centres.push_back({{m.s[0] / m.w, m.s[1] / m.w, m.s[2] / m.w}, m.w});
  }
  refine_centres(points, centres, 12);
  std::vector<PaletteColor> palette;
  for (const WeightedColor& c : centres) palette.push_back({to_byte(c.c[0]), to_byte(c.c[1]), to_byte(c.c[2])});
  return palette;
}

PaletteMapper::PaletteMapper(std::vector<PaletteColor> palette)
    : palette_(std::move(palette)), cache_(kCacheSlots, 0) {
  if (palette_.empty() || palette_.size() > 256)
    throw std::invalid_argument("PaletteMapper: 1 to 256 colours");
  by_green_.resize(palette_.size());
  std::iota(by_green_.begin(), by_green_.end(), uint8_t{0});
  std::stable_sort(by_green_.begin(), by_green_.end(),
                   [&](uint8_t a, uint8_t b) { return palette_[a][1] < palette_[b][1]; });
}

// Outwards from the first entry of green >= g, both ways, each way stopping where the green
// difference alone reaches the best squared distance found.
uint8_t PaletteMapper::search(uint8_t r, uint8_t g, uint8_t b) const {
  const auto start = std::lower_bound(by_green_.begin(), by_green_.end(), g,
                                      [&](uint8_t i, uint8_t green) { return palette_[i][1] < green; });
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(by_green_.size());
  std::ptrdiff_t up = start - by_green_.begin(), down = up - 1;
  int best = std::numeric_limits<int>::max();
  uint8_t nearest = 0;
  auto consider = [&](uint8_t i) {
    const PaletteColor& p = palette_[i];
    const int dr = p[0] - r, dg = p[1] - g, db = p[2] - b;
    const int d = dr * dr + dg * dg + db * db;
    if (d < best || (d == best && i < nearest)) {
      best = d;
      nearest = i;
    }
  };
  auto green_gap = [&](std::ptrdiff_t k) {
    const int dg = palette_[by_green_[static_cast<size_t>(k)]][1] - g;
    return dg * dg;
  };
  while (up < n || down >= 0) {
    if (up < n && green_gap(up) > best) up = n;
    if (down >= 0 && green_gap(down) > best) down = -1;
    if (up < n) consider(by_green_[static_cast<size_t>(up++)]);
    if (down >= 0) consider(by_green_[static_cast<size_t>(down--)]);
  }
  return nearest;
}

uint8_t PaletteMapper::index_of(uint8_t r, uint8_t g, uint8_t b) {
  const uint32_t key = uint32_t(r) << 16 | uint32_t(g) << 8 | b;
  uint64_t& slot = cache_[(key * 2654435761u) >> 16 & (kCacheSlots - 1)];
  if (slot >> 8 == uint64_t{key} + 1) return static_cast<uint8_t>(slot & 0xff);
  const uint8_t index = search(r, g, b);
  slot = (uint64_t{key} + 1) << 8 | index;
  return index;
}

void PaletteMapper::map(const uint8_t* rgb, size_t pixels, uint8_t* indices, size_t stride) {
  for (size_t i = 0; i < pixels; ++i) {
    const uint8_t* p = rgb + i * stride;
    indices[i] = index_of(p[0], p[1], p[2]);
  }
}

}  // namespace pyro
