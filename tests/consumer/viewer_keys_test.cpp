// The window component from the installed package: the viewer's key table, with no window
// opened. Keys 1..7 pick the stereo modes in stereo_modes_by_key()'s order, each by the name
// --press-at uses, and the named toggles map to their commands.
#include "tools/viewer/viewer_keys.h"

#include <gtest/gtest.h>

#include <string>

namespace {

using namespace pyro;

TEST(ConsumerViewerKeys, DigitKeysPickTheStereoModesInOrder) {
  const auto& modes = stereo_modes_by_key();
  ASSERT_EQ(modes.size(), 7u);
  for (int i = 0; i < 7; ++i) {
    const auto key = key_from_name(std::to_string(i + 1));
    ASSERT_TRUE(key.has_value()) << "key " << i + 1;
    const auto action = action_for_key(*key, 0);
    ASSERT_TRUE(action.has_value()) << "key " << i + 1;
    EXPECT_EQ(action->command, ViewerCommand::set_stereo);
    EXPECT_EQ(action->stereo, modes[i]) << "key " << i + 1;
  }
}

TEST(ConsumerViewerKeys, NamedTogglesMapToTheirCommands) {
  const std::pair<const char*, ViewerCommand> named[] = {
      {"b", ViewerCommand::toggle_billboards},    {"L", ViewerCommand::cycle_layer_scale},
      {"space", ViewerCommand::toggle_pause},     {"N", ViewerCommand::single_step},
      {"TAB", ViewerCommand::toggle_camera_mode}, {"esc", ViewerCommand::quit}};
  for (const auto& [name, command] : named) {
    const auto key = key_from_name(name);
    ASSERT_TRUE(key.has_value()) << name;
    const auto action = action_for_key(*key, 0);
    ASSERT_TRUE(action.has_value()) << name;
    EXPECT_EQ(action->command, command) << name;
  }
  EXPECT_FALSE(key_from_name("F13").has_value());
}

}  // namespace
