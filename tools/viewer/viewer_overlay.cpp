#include "tools/viewer/viewer_overlay.h"

#include <algorithm>
#include <cstdio>

#include "tools/viewer/viewer_keys.h"

namespace pyro {

std::vector<std::string> wrap_text(const std::string& text, int columns) {
  const size_t width = size_t(std::max(columns, 1));
  std::vector<std::string> lines;
  size_t start = 0;
  while (start <= text.size()) {
    const size_t end = std::min(text.find('\n', start), text.size());
    std::string paragraph = text.substr(start, end - start);
    std::string line;
    size_t i = 0;
    while (i < paragraph.size()) {
      // The next word and the spaces before it (kept between words on one line, dropped at a
      // break).
      const size_t word_start = paragraph.find_first_not_of(' ', i);
      if (word_start == std::string::npos) break;
      const size_t word_end = std::min(paragraph.find(' ', word_start), paragraph.size());
      const size_t spaces = word_start - i;
      std::string word = paragraph.substr(word_start, word_end - word_start);
      i = word_end;
      bool first_piece = true;
      while (!word.empty()) {
        const size_t gap = line.empty() ? 0 : (first_piece ? spaces : 1);
        if (line.size() + gap + word.size() <= width) {
          line += std::string(gap, ' ') + word;
          word.clear();
        } else if (line.empty()) {  // a word longer than a line: cut it
          lines.push_back(word.substr(0, width));
          word.erase(0, width);
          first_piece = false;
        } else {
          lines.push_back(line);
          line.clear();
        }
      }
    }
    lines.push_back(line);
    if (end == text.size()) break;
    start = end + 1;
  }
  return lines;
}

std::string overlay_header(const OverlayInfo& info) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "Status  %.1f fps  frame %llu%s", info.fps, info.frame,
                info.paused ? "  PAUSED" : "");
  return buf;
}

std::vector<OverlayLine> overlay_lines(const OverlayInfo& info, int columns) {
  std::vector<OverlayLine> out;
  const auto add = [&](const std::string& text, bool error) {
    for (std::string& l : wrap_text(text, columns)) out.push_back({std::move(l), error});
  };
  char buf[256];
  std::snprintf(buf, sizeof buf, "%.1f FPS  %.1f MS  FRAME %llu  %zu PARTICLES%s", info.fps,
                info.frame_ms, info.frame, info.particles, info.paused ? "  PAUSED" : "");
  add(buf, false);
  add(info.stereo + "  " + info.billboards + "  LAYER " + info.layer_scale + "  " + info.camera,
      false);
  std::string systems;
  for (const auto& [name, ms] : info.system_ms) {
    std::snprintf(buf, sizeof buf, "%s%s %.2f", systems.empty() ? "" : "  ", name.c_str(), ms);
    systems += buf;
  }
  if (!systems.empty()) add("MS: " + systems, false);
  if (!info.error.empty()) {
    add("RELOAD FAILED, KEEPING THE LAST GOOD SCENE:", true);
    add(info.error, true);
  }
  if (info.help) {
    for (const std::string& l : key_help_lines()) add(l, false);
  } else {
    add("H: KEYS", false);
  }
  return out;
}

}  // namespace pyro
