// Step 3 of a DWA control step (algos/local/dwa_rollout.h), compiled once per instruction-set
// level into a namespace of its own (core/simd_target.h). Plain loops over the lanes that the
// compiler vectorises at the level's width; without FMA contraction (-ffp-contract=off) every
// level rounds each operation as written, so the values are the same bit for bit.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>

#include "algos/local/dwa.h"
#include "algos/local/dwa_rollout.h"
#include "algos/planner.h"
#include "core/cell_blocks.h"
#include "core/grid.h"
#include "core/line_of_sight.h"
#include "core/numbers.h"
#include "core/simd_target.h"

AGV_SIMD_TARGET_BEGIN

namespace agv::dwa_levels::AGV_SIMD_LEVEL {

namespace {

// Squared exact distance from (x, y) to the nearest obstacle square of the 3x3 block around its
// cell, capped at 1: no square outside that block is closer than 1 to any point of the cell.
// Branch-free over the padded occupancy (the border ring makes the 8 neighbours always valid).
inline double capped_static_sq(const std::uint8_t* occ, int stride, int width, int height, double x,
                               double y) {
  if (!(x >= 0.0 && y >= 0.0 && x <= width && y <= height)) return 0.0;  // also catches NaN
  const int cx = std::min(static_cast<int>(x), width);  // x == width lies on the border ring
  const int cy = std::min(static_cast<int>(y), height);
  const double fx = x - cx, fy = y - cy;
  const double gx = 1.0 - fx, gy = 1.0 - fy;
  const std::uint8_t* c = occ + (cy + 1) * stride + (cx + 1);
  const double fx2 = fx * fx, fy2 = fy * fy, gx2 = gx * gx, gy2 = gy * gy;
  double d = 1.0;
  d = std::min(d, c[-1] ? fx2 : 1.0);
  d = std::min(d, c[1] ? gx2 : 1.0);
  d = std::min(d, c[-stride] ? fy2 : 1.0);
  d = std::min(d, c[stride] ? gy2 : 1.0);
  d = std::min(d, c[-stride - 1] ? fx2 + fy2 : 1.0);
  d = std::min(d, c[-stride + 1] ? gx2 + fy2 : 1.0);
  d = std::min(d, c[stride - 1] ? fx2 + gy2 : 1.0);
  d = std::min(d, c[stride + 1] ? gx2 + gy2 : 1.0);
  return c[0] ? 0.0 : d;
}

// capped_static_sq() at every rollout point, in two passes so that the second vectorises: each
// point's cell and the occupancy mask of its 3x3 block (core/cell_blocks.h, one load), then the
// distances of every point at once, without the per-neighbour branches the compiler makes of the
// scalar form. The arithmetic is the scalar form's, term for term: the same values bit for bit.
void capped_static_sq_all(const Grid& grid, DwaScratch& s) {
  const std::uint32_t* blocks = grid.cell_blocks().masks();
  const int stride = grid.stride(), width = grid.width(), height = grid.height();
  const auto n = static_cast<int>(s.px.size());
  const double *px = s.px.data(), *py = s.py.data();
  double *frac_x = s.frac_x.data(), *frac_y = s.frac_y.data();
  std::uint32_t* block = s.block.data();
  for (int i = 0; i < n; ++i) {
    // A point outside the grid (or NaN) reads the corner ring cell at index 0: blocked, so 0.
    const bool inside = (px[i] >= 0.0) & (py[i] >= 0.0) & (px[i] <= width) & (py[i] <= height);
    const double x = inside ? px[i] : -1.0, y = inside ? py[i] : -1.0;
    const int cx = std::min(static_cast<int>(x), width);  // x == width lies on the border ring
    const int cy = std::min(static_cast<int>(y), height);
    frac_x[i] = x - cx;
    frac_y[i] = y - cy;
    block[i] = static_cast<std::uint32_t>((cy + 1) * stride + (cx + 1));
  }
  // The gather on its own: GCC vectorises the loops around it only without it.
  for (int i = 0; i < n; ++i) block[i] = blocks[block[i]];
  for (int i = 0; i < n; ++i) {
    const std::uint32_t m = s.block[i];
    const double fx = s.frac_x[i], fy = s.frac_y[i];
    const double gx = 1.0 - fx, gy = 1.0 - fy;
    const double fx2 = fx * fx, fy2 = fy * fy, gx2 = gx * gx, gy2 = gy * gy;
    double d = 1.0;
    d = std::min(d, m & kBlockLeft ? fx2 : 1.0);
    d = std::min(d, m & kBlockRight ? gx2 : 1.0);
    d = std::min(d, m & kBlockUp ? fy2 : 1.0);
    d = std::min(d, m & kBlockDown ? gy2 : 1.0);
    d = std::min(d, m & kBlockUpLeft ? fx2 + fy2 : 1.0);
    d = std::min(d, m & kBlockUpRight ? gx2 + fy2 : 1.0);
    d = std::min(d, m & kBlockDownLeft ? fx2 + gy2 : 1.0);
    d = std::min(d, m & kBlockDownRight ? gx2 + gy2 : 1.0);
    s.step_static[i] = m & kBlockCentre ? 0.0 : d;
  }
}

// One rollout step of every lane: the chord along the current direction, then the direction
// turned by w dt. The arrays are distinct (restrict), which lets the loop vectorise.
void advance_lanes(int n, double* __restrict px, double* __restrict py, double* __restrict ux,
                   double* __restrict uy, const double* __restrict chord,
                   const double* __restrict rot_c, const double* __restrict rot_s) {
  for (int i = 0; i < n; ++i) {
    px[i] = px[i] + chord[i] * ux[i];
    py[i] = py[i] + chord[i] * uy[i];
    const double x = ux[i];
    ux[i] = x * rot_c[i] - uy[i] * rot_s[i];
    uy[i] = x * rot_s[i] + uy[i] * rot_c[i];
  }
}

// Step 3 (algos/local/dwa_rollout.h).
bool roll_out(const DwaParams& p, const Pose& pose, const StepShape& shape, const DwaTarget& target,
              const DwaView& view, DwaScratch& s, DeadlinePoller* poll) {
  const std::span<const Point> goals = target.goals;
  const GoalPassing& passing = target.passing;
  const int n = shape.n, steps = shape.steps;
  const double to_cells = 1.0 / p.cell_edge;

  // Rollout set-up: each step is the exact arc of algos/local/unicycle.h, its chord direction
  // rotating by w dt per step.
  // The trigonometry depends on w alone: worked out once per w sample (the first row of the
  // sample grid, iv = 0) and copied to the other rows, the same values bit for bit.
  const int nw = shape.nw;
  for (int i = 0; i < n; ++i) {
    const double half = 0.5 * p.dt * s.w[i];
    if (i < nw) {
      s.turn_sinc[i] = sinc(half);
      s.ux[i] = std::cos(pose.theta + half);
      s.uy[i] = std::sin(pose.theta + half);
      s.rot_c[i] = std::cos(2.0 * half);
      s.rot_s[i] = std::sin(2.0 * half);
    } else {
      const int iw = i % nw;
      s.ux[i] = s.ux[iw];
      s.uy[i] = s.uy[iw];
      s.rot_c[i] = s.rot_c[iw];
      s.rot_s[i] = s.rot_s[iw];
    }
    s.chord[i] = s.v[i] * to_cells * p.dt * s.turn_sinc[i % nw];
  }
  std::fill_n(s.px.data(), n, pose.x);
  std::fill_n(s.py.data(), n, pose.y);

  // collision_checks (docs/METRICS.md "Work counters"): one per rollout point, whatever number
  // of obstacles it is measured against.
  count_collision_checks(static_cast<std::int64_t>(n) * steps);
  const std::uint8_t* occ = view.known.occupancy();
  const int stride = view.known.stride(), width = view.known.width(), height = view.known.height();
  const double dyn_cap = std::max(p.dynamic_clearance_cap, p.robot_radius + p.safety_margin);

  // Clearance of the current position: a robot already inside the safety band (a moving obstacle
  // came close, an unknown cell was just seen) must still be able to move away, so the hit
  // threshold is lowered to just below where it stands, for that class of obstacle only (a
  // moving disc close by must not let the robot graze a wall).
  double now_other = dyn_cap;
  for (const Cell& c : view.unknown) {
    const double dx = std::max({c.x - pose.x, 0.0, pose.x - (c.x + 1.0)});
    const double dy = std::max({c.y - pose.y, 0.0, pose.y - (c.y + 1.0)});
    now_other = std::min(now_other, std::sqrt(dx * dx + dy * dy));
  }
  for (const Disc& d : view.moving)
    now_other = std::min(now_other, std::hypot(pose.x - d.centre.x, pose.y - d.centre.y) -
                                        d.radius - p.dynamic_margin);
  const double now_static = std::sqrt(capped_static_sq(occ, stride, width, height, pose.x, pose.y));
  auto threshold_at = [&](double now) {
    return p.robot_radius + std::clamp(now - p.robot_radius - 1e-6, 0.0, p.safety_margin);
  };
  const double threshold_static = threshold_at(now_static);
  const double threshold_other = threshold_at(now_other);

  std::fill_n(s.min_static.data(), n, 1.0);
  std::fill_n(s.min_other.data(), n, dyn_cap);
  std::fill_n(s.hit_static.data(), n, steps + 1.0);
  std::fill_n(s.hit_other.data(), n, steps + 1.0);
  std::fill_n(s.goal_index.data(), n, 0.0);
  const auto goal_count = static_cast<int>(goals.size());
  const double tol2 = passing.tolerance * passing.tolerance;
  const double radius2 = passing.radius * passing.radius;
  double *px = s.px.data(), *py = s.py.data(), *ux = s.ux.data(), *uy = s.uy.data();
  const double *chord = s.chord.data(), *rot_c = s.rot_c.data(), *rot_s = s.rot_s.data();
  double *step_static = s.step_static.data(), *step_other = s.step_other.data();
  double *hit_static = s.hit_static.data(), *hit_other = s.hit_other.data();
  double *min_static = s.min_static.data(), *min_other = s.min_other.data();
  double* goal_index = s.goal_index.data();
  for (int k = 1; k <= steps; ++k) {
    if (poll_expired(poll)) return false;
    const double kk = k;
    // Plain loops over the lanes rather than Eigen expressions: Eigen evaluates a select() of a
    // combined comparison one coefficient at a time, with branches. Each statement keeps the
    // expression's operations in its order, so the values are the same bit for bit.
    advance_lanes(n, px, py, ux, uy, chord, rot_c, rot_s);
    capped_static_sq_all(view.known, s);
    // std::sqrt in a plain loop, not Eigen's: with EIGEN_FAST_MATH=0 (CMakeLists.txt, for results
    // that do not depend on the build) Eigen takes AVX-512's doubles one at a time, while GCC
    // vectorises this loop with the correctly rounded packet root (-fno-math-errno).
    for (int i = 0; i < n; ++i) step_static[i] = std::sqrt(step_static[i]);
    for (int i = 0; i < n; ++i) {
      hit_static[i] =
          ((step_static[i] < threshold_static) & (hit_static[i] > steps)) ? kk : hit_static[i];
      min_static[i] = std::min(min_static[i], step_static[i]);
      step_other[i] = dyn_cap;
    }
    // Plain loops for the same reason; without FMA contraction (-ffp-contract=off) their sums of
    // squares round as written, on every build.
    for (const Cell& c : view.unknown) {
      const double x0 = c.x, x1 = c.x + 1.0, y0 = c.y, y1 = c.y + 1.0;
      for (int i = 0; i < n; ++i) {
        const double ex = std::max(std::max(x0 - px[i], px[i] - x1), 0.0);
        const double ey = std::max(std::max(y0 - py[i], py[i] - y1), 0.0);
        step_other[i] = std::min(step_other[i], std::sqrt(ex * ex + ey * ey));
      }
    }
    for (const Disc& d : view.moving) {
      const double cx = d.centre.x + d.velocity.x * k * p.dt;
      const double cy = d.centre.y + d.velocity.y * k * p.dt;
      for (int i = 0; i < n; ++i) {
        const double ex = px[i] - cx, ey = py[i] - cy;
        step_other[i] =
            std::min(step_other[i], std::sqrt(ex * ex + ey * ey) - d.radius - p.dynamic_margin);
      }
    }
    for (int i = 0; i < n; ++i) {
      hit_other[i] =
          ((step_other[i] < threshold_other) & (hit_other[i] > steps)) ? kk : hit_other[i];
      min_other[i] = std::min(min_other[i], step_other[i]);
    }
    for (int j = 0; j < goal_count; ++j) {
      // passes_goal() on every rollout point at once.
      const Point g = goals[static_cast<std::size_t>(j)];
      const Point a = j == 0 ? target.from : goals[static_cast<std::size_t>(j - 1)];
      const double dx = g.x - a.x, dy = g.y - a.y;
      const double passed = j, next = j + 1;
      for (int i = 0; i < n; ++i) {
        const double ex = px[i] - g.x, ey = py[i] - g.y;
        const double d2 = ex * ex + ey * ey;
        const bool pass = (d2 <= tol2) | ((d2 <= radius2) & (ex * dx + ey * dy >= 0.0));
        goal_index[i] = ((goal_index[i] == passed) & pass) ? next : goal_index[i];
      }
    }
  }
  return true;
}

}  // namespace

double capped_static_sq_at(const Grid& grid, double x, double y) {
  return capped_static_sq(grid.occupancy(), grid.stride(), grid.width(), grid.height(), x, y);
}

extern const DwaRolloutKernel kKernel{roll_out, capped_static_sq_at};

}  // namespace agv::dwa_levels::AGV_SIMD_LEVEL

AGV_SIMD_TARGET_END
