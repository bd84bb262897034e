#include "tools/viewer/viewer_settings.h"

namespace pyro {

float next_layer_scale(float scale) {
  if (scale == 1.0f) return 0.5f;
  if (scale == 0.5f) return 0.25f;
  if (scale == 0.25f) return 0.125f;
  return 1.0f;
}

const char* layer_scale_name(float scale) {
  if (scale == 0.5f) return "1/2";
  if (scale == 0.25f) return "1/4";
  if (scale == 0.125f) return "1/8";
  return "1";
}

std::string upper_case(std::string_view name) {
  std::string text(name);
  for (char& c : text)
    if (c >= 'a' && c <= 'z') c = char(c - 'a' + 'A');
  return text;
}

ViewerEffect apply_action(ViewerSettings& s, const ViewerAction& a) {
  ViewerEffect e;
  switch (a.command) {
    case ViewerCommand::quit: e.quit = true; break;
    case ViewerCommand::toggle_camera_mode: e.toggle_camera_mode = true; break;
    case ViewerCommand::set_stereo:
      e.rebuild_runtime = s.stereo != a.stereo;
      s.stereo = a.stereo;
      break;
    case ViewerCommand::toggle_billboards:
      s.billboards = s.billboards == BillboardAlignment::viewplane ? BillboardAlignment::viewpoint
                                                                  : BillboardAlignment::viewplane;
      e.rebuild_runtime = true;
      break;
    case ViewerCommand::cycle_layer_scale:
      s.layer_scale = next_layer_scale(s.layer_scale);
      e.rebuild_runtime = true;
      break;
    case ViewerCommand::toggle_pause:
      s.paused = !s.paused;
      s.pending_steps = 0;
      break;
    case ViewerCommand::single_step:
      s.paused = true;
      ++s.pending_steps;
      break;
    case ViewerCommand::reload: e.reload_scene = true; break;
    case ViewerCommand::toggle_overlay: s.overlay = !s.overlay; break;
    case ViewerCommand::toggle_help: s.help = !s.help; break;
    case ViewerCommand::undo: e.undo = true; break;
    case ViewerCommand::redo: e.redo = true; break;
    case ViewerCommand::save: e.save = true; break;
  }
  return e;
}

}  // namespace pyro
