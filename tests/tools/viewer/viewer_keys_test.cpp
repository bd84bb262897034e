// pyro view's keys and what they change, without a window.
#include "tools/viewer/viewer_keys.h"

#include <gtest/gtest.h>

#include <set>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "tools/viewer/viewer_settings.h"

namespace pyro {
namespace {

TEST(ViewerKeys, EveryDocumentedKeyHasItsAction) {
  EXPECT_EQ(action_for_key(GLFW_KEY_ESCAPE, 0), ViewerAction{ViewerCommand::quit});
  EXPECT_EQ(action_for_key(GLFW_KEY_TAB, 0), ViewerAction{ViewerCommand::toggle_camera_mode});
  EXPECT_EQ(action_for_key(GLFW_KEY_B, 0), ViewerAction{ViewerCommand::toggle_billboards});
  EXPECT_EQ(action_for_key(GLFW_KEY_L, 0), ViewerAction{ViewerCommand::cycle_layer_scale});
  EXPECT_EQ(action_for_key(GLFW_KEY_SPACE, 0), ViewerAction{ViewerCommand::toggle_pause});
  EXPECT_EQ(action_for_key(GLFW_KEY_N, 0), ViewerAction{ViewerCommand::single_step});
  EXPECT_EQ(action_for_key(GLFW_KEY_R, 0), ViewerAction{ViewerCommand::reload});
  EXPECT_EQ(action_for_key(GLFW_KEY_O, 0), ViewerAction{ViewerCommand::toggle_overlay});
  EXPECT_EQ(action_for_key(GLFW_KEY_H, 0), ViewerAction{ViewerCommand::toggle_help});
  // Keys 1..7 choose seven different stereo modes, mono first.
  std::set<StereoMode> modes;
  for (int k = GLFW_KEY_1; k <= GLFW_KEY_7; ++k) {
    const auto a = action_for_key(k, 0);
    ASSERT_TRUE(a);
    EXPECT_EQ(a->command, ViewerCommand::set_stereo);
    modes.insert(a->stereo);
  }
  EXPECT_EQ(modes.size(), 7u);
  EXPECT_EQ(action_for_key(GLFW_KEY_1, 0)->stereo, StereoMode::mono);
  EXPECT_EQ(action_for_key(GLFW_KEY_4, 0)->stereo, StereoMode::anaglyph);
}

TEST(ViewerKeys, FlyKeysAndModifiedKeysHaveNoPressAction) {
  for (int k : {GLFW_KEY_W, GLFW_KEY_A, GLFW_KEY_S, GLFW_KEY_D, GLFW_KEY_Q, GLFW_KEY_E, GLFW_KEY_8})
    EXPECT_FALSE(action_for_key(k, 0)) << k;
  EXPECT_FALSE(action_for_key(GLFW_KEY_R, GLFW_MOD_CONTROL));  // Ctrl+R is not a reload
  EXPECT_TRUE(action_for_key(GLFW_KEY_R, GLFW_MOD_SHIFT));
}

TEST(ViewerKeys, ControlKeysUndoRedoAndSaveTheInspectorsEdits) {
  EXPECT_EQ(action_for_key(GLFW_KEY_Z, GLFW_MOD_CONTROL), ViewerAction{ViewerCommand::undo});
  EXPECT_EQ(action_for_key(GLFW_KEY_Z, GLFW_MOD_CONTROL | GLFW_MOD_SHIFT), ViewerAction{ViewerCommand::redo});
  EXPECT_EQ(action_for_key(GLFW_KEY_Y, GLFW_MOD_CONTROL), ViewerAction{ViewerCommand::redo});
  EXPECT_EQ(action_for_key(GLFW_KEY_S, GLFW_MOD_CONTROL), ViewerAction{ViewerCommand::save});
  EXPECT_FALSE(action_for_key(GLFW_KEY_Z, 0));  // Z alone does nothing
  EXPECT_FALSE(action_for_key(GLFW_KEY_S, GLFW_MOD_CONTROL | GLFW_MOD_ALT));
  ViewerSettings settings;
  const ViewerSettings before = settings;
  const ViewerEffect undo = apply_action(settings, ViewerAction{ViewerCommand::undo});
  EXPECT_TRUE(undo.undo);
  EXPECT_FALSE(undo.redo || undo.save || undo.rebuild_runtime || undo.reload_scene);
  EXPECT_TRUE(apply_action(settings, ViewerAction{ViewerCommand::redo}).redo);
  EXPECT_TRUE(apply_action(settings, ViewerAction{ViewerCommand::save}).save);
  EXPECT_EQ(settings.paused, before.paused);  // the document's actions change no view setting
  EXPECT_EQ(settings.stereo, before.stereo);
}

TEST(ViewerKeys, KeyNamesForScriptedPresses) {
  EXPECT_EQ(key_from_name("1"), GLFW_KEY_1);
  EXPECT_EQ(key_from_name("7"), GLFW_KEY_7);
  EXPECT_EQ(key_from_name("space"), GLFW_KEY_SPACE);
  EXPECT_EQ(key_from_name("Esc"), GLFW_KEY_ESCAPE);
  EXPECT_EQ(key_from_name("TAB"), GLFW_KEY_TAB);
  EXPECT_EQ(key_from_name("b"), GLFW_KEY_B);
  for (const char* bad : {"8", "0", "", "F5", "SPACEBAR", "W"}) EXPECT_FALSE(key_from_name(bad)) << bad;
  // Every named key has an action.
  for (const char* name : {"1", "2", "3", "4", "5", "6", "7", "B", "L", "N", "R", "O", "H", "SPACE", "TAB", "ESC"})
    EXPECT_TRUE(action_for_key(*key_from_name(name), 0)) << name;
}

TEST(ViewerKeys, HeldKeysGiveTheMoveDirection) {
  HeldKeys k;
  EXPECT_EQ(move_direction(k), glm::vec3(0.0f));
  k.forward = true;
  k.right = true;
  k.down = true;
  EXPECT_EQ(move_direction(k), glm::vec3(1.0f, -1.0f, 1.0f));
  k.back = true;  // forward and back cancel
  k.left = true;
  EXPECT_EQ(move_direction(k), glm::vec3(0.0f, -1.0f, 0.0f));
  EXPECT_EQ(move_speed_factor(k), 1.0f);
  k.fast = true;
  EXPECT_EQ(move_speed_factor(k), 4.0f);
}

TEST(ViewerSettings, LayerScaleCyclesThroughTheFourScales) {
  float s = 1.0f;
  const float expected[] = {0.5f, 0.25f, 0.125f, 1.0f, 0.5f};
  for (float e : expected) {
    s = next_layer_scale(s);
    EXPECT_EQ(s, e);
  }
  EXPECT_EQ(next_layer_scale(0.3f), 1.0f);
  EXPECT_STREQ(layer_scale_name(0.125f), "1/8");
}

TEST(ViewerSettings, ActionsChangeTheSettingsAndSayWhatMustFollow) {
  ViewerSettings s;
  auto e = apply_action(s, {ViewerCommand::set_stereo, StereoMode::anaglyph});
  EXPECT_TRUE(e.rebuild_runtime);
  EXPECT_EQ(s.stereo, StereoMode::anaglyph);
  e = apply_action(s, {ViewerCommand::set_stereo, StereoMode::anaglyph});
  EXPECT_FALSE(e.rebuild_runtime);  // the same mode again: nothing to rebuild
  e = apply_action(s, {ViewerCommand::toggle_billboards});
  EXPECT_TRUE(e.rebuild_runtime);
  EXPECT_EQ(s.billboards, BillboardAlignment::viewpoint);
  apply_action(s, {ViewerCommand::toggle_billboards});
  EXPECT_EQ(s.billboards, BillboardAlignment::viewplane);
  e = apply_action(s, {ViewerCommand::cycle_layer_scale});
  EXPECT_TRUE(e.rebuild_runtime);
  EXPECT_EQ(s.layer_scale, 0.5f);

  // Pause, single steps (each pauses and queues one step), unpause drops queued steps.
  EXPECT_FALSE(s.paused);
  apply_action(s, {ViewerCommand::single_step});
  apply_action(s, {ViewerCommand::single_step});
  EXPECT_TRUE(s.paused);
  EXPECT_EQ(s.pending_steps, 2);
  apply_action(s, {ViewerCommand::toggle_pause});
  EXPECT_FALSE(s.paused);
  EXPECT_EQ(s.pending_steps, 0);

  EXPECT_TRUE(apply_action(s, {ViewerCommand::reload}).reload_scene);
  EXPECT_TRUE(apply_action(s, {ViewerCommand::quit}).quit);
  EXPECT_TRUE(apply_action(s, {ViewerCommand::toggle_camera_mode}).toggle_camera_mode);
  const bool overlay = s.overlay;
  EXPECT_FALSE(apply_action(s, {ViewerCommand::toggle_overlay}).rebuild_runtime);
  EXPECT_NE(s.overlay, overlay);
  apply_action(s, {ViewerCommand::toggle_help});
  EXPECT_TRUE(s.help);
}

}  // namespace
}  // namespace pyro
