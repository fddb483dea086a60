// GCC 12 flags the `_mm512_undefined_pd()` placeholders inside its own AVX-512 intrinsics once
// Eigen's packet min/max/sqrt are inlined here (a known false positive of -Wmaybe-uninitialized,
// GCC bug 105593); nothing of ours is uninitialised. Before the includes: the warning is
// reported at the intrinsics header's lines.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"

#include "algos/local/dwa.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "algos/local/dwa_rollout.h"
#include "core/numbers.h"

namespace agv {

namespace {

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
  return std::sqrt(active_dwa_rollout_kernel().capped_static_sq(grid, p.x, p.y));
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
  if (!active_dwa_rollout_kernel().roll_out(p, pose, shape, target, view, s, poll)) {
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
