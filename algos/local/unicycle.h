#pragma once
// The robot's motion model (paper 003 eq. 7, paper 004 section 3.1): a unicycle,
//   x' = v cos(theta), y' = v sin(theta), theta' = w.
// The papers integrate it with Euler steps; for constant (v, w) over one step the motion is an
// exact circular arc, and that is what is integrated here, in the numerically stable chord form
//   dx = v dt sinc(w dt / 2) cos(theta + w dt / 2),  dy = v dt sinc(w dt / 2) sin(theta + w dt / 2)
// (sin(a + b) - sin(a) = 2 cos(a + b/2) sin(b/2)), which is exact for any w, including w = 0,
// where it is the straight line. Composing steps of one (v, w) therefore reproduces the closed
// form of the whole arc (tests/algos/test_dwa.cpp), and the DWA's rollout of a velocity pair is
// exactly the path the robot then drives.
//
// Units are the caller's: the DWA works in cells and cells per second (metres / cell edge).

#include <cmath>

#include "core/grid.h"
#include "core/numbers.h"

namespace agv {

struct Pose {
  double x = 0.0;
  double y = 0.0;
  double theta = 0.0;  // rad, atan2 convention in the grid's (x, y) frame
};

// sin(u) / u, with its Taylor series near 0 (no division by zero, full precision).
inline double sinc(double u) {
  if (std::abs(u) < 1e-4) return 1.0 - u * u / 6.0;
  return std::sin(u) / u;
}

// One step of constant (v, w) for dt: the exact arc.
inline Pose unicycle_step(const Pose& p, double v, double w, double dt) {
  const double half = 0.5 * w * dt;
  const double chord = v * dt * sinc(half);
  return {p.x + chord * std::cos(p.theta + half), p.y + chord * std::sin(p.theta + half),
          p.theta + w * dt};
}

inline Point position(const Pose& p) { return {p.x, p.y}; }

// Wraps an angle to (-pi, pi].
inline double wrap_angle(double a) {
  a = std::remainder(a, 2.0 * kPi);
  if (a <= -kPi) a += 2.0 * kPi;
  return a;
}

}  // namespace agv
