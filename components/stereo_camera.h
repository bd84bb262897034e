#pragma once
// Makes a Camera entity stereo: two eyes from off-axis projections with parallel view axes
// (engine/math/stereo_projection.h). Both eyes render the same simulation state.
#include "engine/core/enum_names.h"
#include "engine/math/stereo_projection.h"

namespace pyro {

// Which eye's view goes where the output expects the left one: the left eye (the usual), or
// the right (glasses worn the other way round, a projector pair wired crossed).
enum class EyeOrder { left_right, right_left };
inline constexpr EnumName<EyeOrder> eye_order_names[] = {{EyeOrder::left_right, "left-right"},
                                                      {EyeOrder::right_left, "right-left"}};
constexpr const auto& enum_names(EyeOrder) { return eye_order_names; }

struct StereoCamera {
  StereoParameters parameters;
  EyeOrder eye_order = EyeOrder::left_right;
};

}  // namespace pyro
