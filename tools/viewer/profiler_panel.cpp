#include "tools/viewer/profiler_panel.h"

#include <imgui.h>

#include <cfloat>
#include <cstdio>

namespace pyro {

namespace {

void plot_series(const FrameTimeHistory& history, const char* unit) {
  for (const std::string& name : history.names()) {
    const std::vector<float> values = history.values(name);
    char overlay[96];
    std::snprintf(overlay, sizeof overlay, "mean %.3g, max %.3g %s", history.mean(name),
                  history.max(name), unit);
    ImGui::PlotLines(name.c_str(), values.data(), int(values.size()), 0, overlay, 0.0f, FLT_MAX,
                     ImVec2(0, 36 * ImGui::GetIO().FontGlobalScale));
  }
}

void particle_table(const ProfilerView& v) {
  ImGui::Text("particles: %llu live of %llu, %zu drawn", (unsigned long long)v.census.live,
              (unsigned long long)v.census.capacity, v.drawn);
  if (v.census.sources.empty() || !ImGui::TreeNode("per source")) return;
  for (const ParticleSourceCount& s : v.census.sources)
    ImGui::Text("%s: %llu / %llu", s.name.c_str(), (unsigned long long)s.live,
                (unsigned long long)s.capacity);
  ImGui::TreePop();
}

}  // namespace

ProfilerRequest draw_profiler_panel(const ProfilerView& v, DockedPanel& panel) {
  ProfilerRequest request;
  const DockedPart part = begin_docked_panel("Profiler", panel);
  if (part == DockedPart::body) {
    ImGui::PushItemWidth(-ImGui::GetFontSize() * 9.0f);  // room for the longest system name
    ImGui::Text("%.1f fps, %.2f ms per frame, frame %llu", v.fps, v.frame_ms, (unsigned long long)v.frame);
    particle_table(v);
    if (ImGui::CollapsingHeader("systems, ms", ImGuiTreeNodeFlags_DefaultOpen) && v.systems)
      plot_series(*v.systems, "ms");
    bool gpu = v.gpu_profiling;
    if (ImGui::Checkbox("GPU passes (timer and fragment queries)", &gpu)) request.toggle_gpu_profiling = true;
    if (v.gpu_profiling && v.fragments && ImGui::CollapsingHeader("fragments per pass"))
      plot_series(*v.fragments, "fragments");
    if (ImGui::CollapsingHeader("assets")) {
      for (const auto& [name, count] : v.asset_counters)
        ImGui::Text("%s: %llu", name.c_str(), (unsigned long long)count);
    }
    ImGui::PopItemWidth();
  }
  end_docked_panel(part);
  return request;
}

}  // namespace pyro
