// GCC 12 flags the `_mm512_undefined_pd()` placeholders inside its own AVX-512 intrinsics once
// Eigen's packet min/max/sqrt are inlined here (a known false positive of -Wmaybe-uninitialized,
// GCC bug 105593); nothing of ours is uninitialised. Before the includes: the warning is
// reported at the intrinsics header's lines.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"

#include "algos/local/dwa.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/cell_blocks.h"
#include "core/line_of_sight.h"
#include "core/numbers.h"

namespace agv {

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

// Samples n points over [lo, hi], endpoints included (one point: the middle).
inline double sample_at(double lo, double hi, int i, int n) {
  if (n <= 1) return 0.5 * (lo + hi);
  return lo + (hi - lo) * static_cast<double>(i) / static_cast<double>(n - 1);
}

}  // namespace

const char* to_string(DwaScore s) {
  switch (s) {
    case DwaScore::classic:
      return "classic";
    case DwaScore::improved_003:
      return "improved_003";
    case DwaScore::following_004:
      return "following_004";
  }
  return "unknown";
}

DwaWeights default_weights(DwaScore s) {
  switch (s) {
    case DwaScore::improved_003:
      return {0.2, 0.4, 0.2, 0.35};
    case DwaScore::classic:
    case DwaScore::following_004:
      return {0.2, 0.1, 0.3, 0.0};
  }
  return {};
}

double capped_static_clearance(const Grid& grid, Point p) {
  return std::sqrt(
      capped_static_sq(grid.occupancy(), grid.stride(), grid.width(), grid.height(), p.x, p.y));
}

Point aim_point(Point a, Point b, Point p, double lookahead) {
  const double ux = b.x - a.x, uy = b.y - a.y;
  const double len = std::hypot(ux, uy);
  if (len < 1e-12) return b;
  const double along = ((p.x - a.x) * ux + (p.y - a.y) * uy) / len + lookahead;
  if (along >= len) return b;
  const double t = std::max(0.0, along) / len;
  return {a.x + t * ux, a.y + t * uy};
}

bool passes_goal(Point p, Point prev, Point goal, const GoalPassing& rule) {
  const double dx = p.x - goal.x, dy = p.y - goal.y;
  const double d2 = dx * dx + dy * dy;
  if (d2 <= rule.tolerance * rule.tolerance) return true;
  if (d2 > rule.radius * rule.radius) return false;
  return dx * (goal.x - prev.x) + dy * (goal.y - prev.y) >= 0.0;
}

VelocityWindow dynamic_window(const DwaParams& p, double v, double w) {
  // Eq. 9 (reachable in one control period) intersected with eq. 8 (limits, v_min = 0).
  VelocityWindow win;
  win.v_lo = std::max(0.0, v - p.acc_v * p.dt);
  win.v_hi = std::min(p.v_max, v + p.acc_v * p.dt);
  win.w_lo = std::max(-p.w_max, w - p.acc_w * p.dt);
  win.w_hi = std::min(p.w_max, w + p.acc_w * p.dt);
  if (win.v_lo > win.v_hi) win.v_lo = win.v_hi = std::clamp(v, 0.0, p.v_max);
  if (win.w_lo > win.w_hi) win.w_lo = win.w_hi = std::clamp(w, -p.w_max, p.w_max);
  return win;
}

namespace {

// The sample grid and rollout length of one control step.
struct StepShape {
  int nv = 1, nw = 1, n = 1;
  int steps = 1;  // K = round(predict_time / dt)
};

StepShape step_shape(const DwaParams& p) {
  StepShape shape;
  shape.nv = std::max(1, p.v_samples);
  shape.nw = std::max(1, p.w_samples);
  shape.n = shape.nv * shape.nw;
  shape.steps = std::max(1, static_cast<int>(std::lround(p.predict_time / p.dt)));
  return shape;
}

// dist(v, w) of eq. 10: the arc length (m) to the last rollout point before a hit at step k,
// less the v dt the robot drives before the next control step can brake. Without that reserve
// the braking chain loses up to one rollout step per control step and a robot at speed runs out
// of admissible pairs before the obstacle.
inline double stop_arc(double v, double k, int steps, double dt) {
  return k <= steps ? std::max(0.0, v * (k - 2.0) * dt) : kInf;
}

// Step 1: V_m n V_d, its upper linear velocity capped by the target's speed cap.
VelocityWindow capped_window(const DwaParams& p, double v, double w, const DwaTarget& target) {
  VelocityWindow win = dynamic_window(p, v, w);
  if (target.speed_cap < win.v_hi) win.v_hi = std::max(win.v_lo, target.speed_cap);
  return win;
}

// Step 2: the n_v x n_w pairs on a regular grid over the window (scratch sized for them).
void sample_pairs(const VelocityWindow& win, const StepShape& shape, DwaScratch& s) {
  for (auto* a : {&s.v,          &s.w,          &s.px,        &s.py,         &s.ux,
                  &s.uy,         &s.chord,      &s.rot_c,     &s.rot_s,      &s.step_static,
                  &s.step_other, &s.min_static, &s.min_other, &s.hit_static, &s.hit_other,
                  &s.goal_index, &s.heading,    &s.velocity,  &s.dist,       &s.dist_dyna,
                  &s.score,      &s.smoothed,   &s.turn_sinc, &s.frac_x,     &s.frac_y})
    a->resize(shape.n);
  s.admissible.resize(shape.n);
  s.block.resize(shape.n);
  const int nv = shape.nv, nw = shape.nw;
  for (int iv = 0; iv < nv; ++iv)
    for (int iw = 0; iw < nw; ++iw) {
      s.v[iv * nw + iw] = sample_at(win.v_lo, win.v_hi, iv, nv);
      s.w[iv * nw + iw] = sample_at(win.w_lo, win.w_hi, iw, nw);
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

// Step 3: every pair rolled out at once: per rollout, the first hit step (static, other), the
// minimum clearances and how many local goals it has passed.
// False when `poll` expired first.
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
  s.px.setConstant(pose.x);
  s.py.setConstant(pose.y);

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

  s.min_static.setConstant(1.0);
  s.min_other.setConstant(dyn_cap);
  s.hit_static.setConstant(steps + 1);
  s.hit_other.setConstant(steps + 1);
  s.goal_index.setZero();
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
          (step_static[i] < threshold_static) & (hit_static[i] > steps) ? kk : hit_static[i];
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
      hit_other[i] = (step_other[i] < threshold_other) & (hit_other[i] > steps) ? kk : hit_other[i];
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
        goal_index[i] = (goal_index[i] == passed) & pass ? next : goal_index[i];
      }
    }
  }
  return true;
}

// Step 4: V_a (eq. 10), dist(v, w) = arc length to the last rollout point before the first hit.
struct Admissibility {
  bool any = false;
  bool moving = false;  // some admissible pair has v > 0
};

Admissibility admissible_pairs(const DwaParams& p, const StepShape& shape, DwaScratch& s) {
  Admissibility out;
  for (int i = 0; i < shape.n; ++i) {
    const double stop =
        stop_arc(s.v[i], std::min(s.hit_static[i], s.hit_other[i]), shape.steps, p.dt);  // m
    bool ok = s.v[i] <= std::sqrt(2.0 * stop * p.acc_v) + 1e-12;
    if (p.va_omega) ok = ok && std::abs(s.w[i]) <= std::sqrt(2.0 * stop * p.acc_w) + 1e-12;
    s.admissible[i] = ok;
    out.any = out.any || ok;
    out.moving = out.moving || (ok && s.v[i] > 1e-9);
  }
  return out;
}

// Step 5, the terms: heading, velocity and the clearance terms of every rollout.
void score_terms(const DwaParams& p, const Pose& pose, const StepShape& shape,
                 const DwaTarget& target, DwaScratch& s) {
  const std::span<const Point> goals = target.goals;
  const auto goal_count = static_cast<int>(goals.size());
  const int n = shape.n, steps = shape.steps;
  // Heading (Fox): pi - |angle between the end heading and the goal direction seen from the end
  // point| (paper 003 Head / Heading, paper 004 PHead).
  const double horizon = steps * p.dt;
  for (int i = 0; i < n; ++i) {
    // Only admissible pairs are scored (score_pairs, best_pair): the others' atan2 is skipped.
    if (!s.admissible[i]) {
      s.heading[i] = 0.0;
      continue;
    }
    const auto gi = static_cast<int>(s.goal_index[i]);
    if (gi >= goal_count) {
      s.heading[i] = kPi;  // the rollout reaches the goal
      continue;
    }
    Point goal = goals[static_cast<std::size_t>(gi)];
    if (target.aim_segment)
      goal = aim_point(gi == 0 ? target.from : goals[static_cast<std::size_t>(gi - 1)], goal,
                       {s.px[i], s.py[i]}, target.lookahead);
    const double end_theta = pose.theta + s.w[i] * horizon;
    const double to_goal = std::atan2(goal.y - s.py[i], goal.x - s.px[i]);
    s.heading[i] = kPi - std::abs(wrap_angle(to_goal - end_theta));
  }
  s.velocity = s.v;
  if (p.dist_mode == DwaParams::DistMode::collision) {
    for (int i = 0; i < n; ++i) {
      s.dist[i] = std::min(p.dist_cap, stop_arc(s.v[i], s.hit_static[i], steps, p.dt));
      s.dist_dyna[i] = std::min(p.dist_cap, stop_arc(s.v[i], s.hit_other[i], steps, p.dt));
    }
  } else {
    s.dist = (s.min_static.min(p.static_clearance_cap) - p.robot_radius).max(0.0);
    s.dist_dyna = (s.min_other - p.robot_radius).max(0.0);
  }
  if (p.score != DwaScore::improved_003) s.dist = s.dist.min(s.dist_dyna);
}

// Step 5, the objective: each term normalised by its sum over the admissible set, weighted and
// added; then the sigma smoothing when asked for.
void score_pairs(const DwaParams& p, const StepShape& shape, DwaScratch& s) {
  auto scale = [&](const Eigen::ArrayXd& term, double weight) {
    const double sum = s.admissible.select(term, 0.0).sum();
    return sum > 0.0 ? weight / sum : 0.0;
  };
  const DwaWeights& wt = p.weights;
  const double dyn_weight = p.score == DwaScore::improved_003 ? wt.dynamic : 0.0;
  const double ch = scale(s.heading, wt.heading), cv = scale(s.velocity, wt.velocity),
               cd = scale(s.dist, wt.clearance), cy = scale(s.dist_dyna, dyn_weight);
  s.score = ch * s.heading + cv * s.velocity + cd * s.dist + cy * s.dist_dyna;
  if (!p.smoothing) return;
  // Sigma: a [1 2 1] x [1 2 1] kernel over the (v, w) sample grid, admissible neighbours only,
  // so a pair whose neighbours are also good wins (Fox et al.: more side clearance).
  const int nv = shape.nv, nw = shape.nw;
  for (int iv = 0; iv < nv; ++iv)
    for (int iw = 0; iw < nw; ++iw) {
      double sum = 0.0, weight = 0.0;
      for (int dv = -1; dv <= 1; ++dv)
        for (int dw = -1; dw <= 1; ++dw) {
          const int jv = iv + dv, jw = iw + dw;
          if (jv < 0 || jv >= nv || jw < 0 || jw >= nw) continue;
          const int j = jv * nw + jw;
          if (!s.admissible[j]) continue;
          const double k = (dv == 0 ? 2.0 : 1.0) * (dw == 0 ? 2.0 : 1.0);
          sum += k * s.score[j];
          weight += k;
        }
      s.smoothed[iv * nw + iw] = weight > 0.0 ? sum / weight : 0.0;
    }
  s.score = s.smoothed;
}

// The best admissible pair; ties go to the first in sample order (deterministic).
int best_pair(const StepShape& shape, const DwaScratch& s) {
  int best = -1;
  for (int i = 0; i < shape.n; ++i)
    if (s.admissible[i] && (best < 0 || s.score[i] > s.score[best])) best = i;
  return best;
}

}  // namespace

DwaDecision dwa_step(const DwaParams& p, const Pose& pose, double v, double w,
                     const DwaTarget& target, const DwaView& view, DwaScratch& s,
                     DeadlinePoller* poll) {
  const StepShape shape = step_shape(p);
  DwaDecision out;
  out.samples = shape.n;
  out.rollout_steps = shape.steps;

  const VelocityWindow win = capped_window(p, v, w, target);
  sample_pairs(win, shape, s);
  if (!roll_out(p, pose, shape, target, view, s, poll)) {
    out.cut = true;
    return out;
  }
  const Admissibility admissible = admissible_pairs(p, shape, s);
  out.any_admissible = admissible.any;
  out.any_moving = admissible.moving;
  if (!admissible.any) {
    // No admissible pair: brake as hard as the window allows, keeping the curvature of the
    // current motion (the arc the last admissible pair was checked along).
    out.v = win.v_lo;
    out.w = std::clamp(v > 1e-9 ? w * win.v_lo / v : 0.0, win.w_lo, win.w_hi);
    return out;
  }
  score_terms(p, pose, shape, target, s);
  score_pairs(p, shape, s);
  const int best = best_pair(shape, s);
  out.v = s.v[best];
  out.w = s.w[best];
  out.stop_distance =
      stop_arc(s.v[best], std::min(s.hit_static[best], s.hit_other[best]), shape.steps, p.dt);
  return out;
}

}  // namespace agv
