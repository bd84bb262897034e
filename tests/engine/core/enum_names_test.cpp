// The vocabulary: every enum <-> name table round-trips (each value has exactly one name and
// each name one value), and the helpers list the names in the table's order. The tables
// themselves live beside their enums; the scene loader and the command line read them
// (tests/systems/runtime/scene/scene_vocabulary_test.cpp checks the messages a bad name gets).
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "components/emitter.h"
#include "components/flipbook_fire.h"
#include "components/mesh_instance.h"
#include "components/particle_medium.h"
#include "components/render_modes.h"
#include "components/render_settings.h"
#include "components/stereo_camera.h"
#include "engine/core/enum_names.h"
#include "engine/math/view_controller.h"

namespace pyro {
namespace {

// Every value the enum has: 0 .. count-1 (the enums are dense, declared without initialisers
// except ParticleMedium, whose 0, 1, 2 are dense too).
template <class E>
void expect_round_trip(int count) {
  std::set<std::string> names;
  for (int i = 0; i < count; ++i) {
    const E value = static_cast<E>(i);
    const std::string_view name = name_of(value);
    EXPECT_FALSE(name.empty());
    EXPECT_TRUE(names.insert(std::string(name)).second) << "two values named " << name;
    ASSERT_TRUE(enum_from_name<E>(name).has_value()) << name;
    EXPECT_EQ(*enum_from_name<E>(name), value) << name;
    EXPECT_EQ(enum_index(value), size_t(i));
  }
  EXPECT_EQ(enum_name_views<E>().size(), size_t(count)) << "the table names values the enum lacks";
  EXPECT_EQ(enum_name_map<E>().size(), size_t(count));
  EXPECT_FALSE(enum_from_name<E>("no-such-name").has_value());
}

TEST(EnumNames, EveryTableRoundTrips) {
  expect_round_trip<StereoMode>(7);
  expect_round_trip<BillboardAlignment>(2);
  expect_round_trip<ParticleShape>(3);
  expect_round_trip<ParticleShading>(2);
  expect_round_trip<EyeOrder>(2);
  expect_round_trip<MeshKind>(7);
  expect_round_trip<ParticleMedium>(3);
  expect_round_trip<EmitterShape>(4);
  expect_round_trip<FlipbookBlend>(2);
  expect_round_trip<CameraControl>(2);
}

TEST(EnumNames, ListsTheNamesInTableOrder) {
  EXPECT_EQ(enum_name_list<ParticleShape>(), "\"gaussian\", \"spherical\", \"planar\"");
  EXPECT_EQ(name_of(StereoMode::side_by_side_crossed), "side-by-side-crossed");
  EXPECT_EQ(name_of(EyeOrder::right_left), "right-left");
  EXPECT_THROW(name_of(static_cast<StereoMode>(99)), std::invalid_argument);
}

}  // namespace
}  // namespace pyro
