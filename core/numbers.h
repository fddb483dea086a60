#pragma once
// The constants several planners and the engine share, defined once (a second definition in an
// anonymous namespace breaks a unity build).

#include <limits>
#include <numbers>

namespace agv {

inline constexpr double kInf = std::numeric_limits<double>::infinity();
inline constexpr double kPi = std::numbers::pi;

}  // namespace agv
