#include "algos/postprocess/postprocess_params.h"

#include <stdexcept>
#include <string>
#include <utility>

#include "algos/postprocess/path_simplify.h"

namespace agv {

namespace {

const ChoiceTable<ShortcutMode>& shortcut_modes() {
  static const ChoiceTable<ShortcutMode> table = {
      {"none", ShortcutMode::none},
      {"collinear", ShortcutMode::collinear},
      {"turning_points", ShortcutMode::turning_points},
      {"greedy", ShortcutMode::greedy},
      {"forward", ShortcutMode::forward},
      {"from_goal", ShortcutMode::from_goal},
      {"direct_midpoint", ShortcutMode::direct_midpoint}};
  return table;
}

const ChoiceTable<SmoothingMode>& smoothing_modes() {
  static const ChoiceTable<SmoothingMode> table = {{"none", SmoothingMode::none},
                                                   {"bezier", SmoothingMode::bezier},
                                                   {"bspline", SmoothingMode::bspline}};
  return table;
}

}  // namespace

ParamDecls<PostprocessOptions> shortcut_decls(ShortcutMode default_mode) {
  ParamDecls<PostprocessOptions> d;
  d.choice("shortcut", &PostprocessOptions::shortcut, default_mode, shortcut_modes(),
           "path shortcut after the search: none; collinear (drop straight-through nodes); "
           "turning_points (paper 000 step 3: drop a turning point whose neighbours see each "
           "other, repeated); greedy (jump to the farthest node in sight); forward (paper 002: "
           "midpoints inserted, then forward key-point search); from_goal (paper 004: greedy from "
           "the goal); direct_midpoint (paper 003: direct, else midpoint shortcut). Never longer "
           "than the search path");
  return d.include([](PostprocessOptions& o) -> PostprocessOptions& { return o; },
                   shortcut_margin_decls(0.0));
}

ParamDecls<PostprocessOptions> shortcut_margin_decls(double default_margin) {
  ParamDecls<PostprocessOptions> d;
  d.number("shortcut_margin", &PostprocessOptions::shortcut_margin, default_margin, 0.0, 10.0,
           "clearance the shortcut segments keep, in cells: every obstacle centre at least "
           "margin + 0.5 away (0 = the segment touches no obstacle cell)");
  return d;
}

ParamDecls<PostprocessOptions> smoothing_decls(SmoothingMode default_mode) {
  ParamDecls<PostprocessOptions> d;
  d.choice("smoothing", &PostprocessOptions::smoothing, default_mode, smoothing_modes(),
           "curve fitting after the shortcut: none; bezier (paper 002 eq. 14: a quadratic Bezier "
           "at each corner, shrunk on collision); bspline (paper 004: clamped cubic uniform "
           "B-spline through the nodes as control points, refitted on collision). Output: the "
           "curve's samples")
      .number(
          "curve_step", [](PostprocessOptions& o) -> double& { return o.bspline.sample_step; }, 0.1,
          0.01, 1.0, "B-spline sample spacing in cells (the curve is returned as samples)")
      .number(
          "bezier_distance",
          [](PostprocessOptions& o) -> double& { return o.bezier.corner_distance; }, 1.0, 0.05,
          10.0,
          "Bezier: distance L of the control points P0, P2 from the corner, cells (clamped to "
          "half of each adjacent segment; paper 002: one cell)")
      .integer(
          "bezier_points", [](PostprocessOptions& o) -> int& { return o.bezier.points_per_curve; },
          10, 2, 1000, "Bezier: samples per corner curve, its two ends included")
      .number("curve_clearance", &PostprocessOptions::curve_clearance, 0.0, 0.0, 10.0,
              "clearance the smoothed curve keeps, in cells: every obstacle centre at least "
              "curve_clearance + 0.5 away (0 = the curve touches no obstacle cell)");
  return d;
}

SightRule sight_rule(CornerRule rule, double margin) {
  return margin > 0.0 ? SightRule::margin(margin, rule) : SightRule::cells(rule);
}

WorkingPath::WorkingPath(std::vector<Point> path) : dense(std::move(path)), points(dense) {
  kept.resize(dense.size());
  for (std::size_t i = 0; i < kept.size(); ++i) kept[i] = static_cast<int>(i);
}

void WorkingPath::keep(const std::vector<int>& local) {
  if (!kept.empty()) {
    std::vector<int> composed;
    composed.reserve(local.size());
    for (int k : local) composed.push_back(kept[k]);
    kept.swap(composed);
  }
  points = select_points(points, local);
}

void WorkingPath::replace(std::vector<Point> path) {
  points = std::move(path);
  kept.clear();
}

void apply_shortcut(const Grid& grid, ShortcutMode mode, const SightRule& sight, WorkingPath& path,
                    DeadlinePoller* poll) {
  switch (mode) {
    case ShortcutMode::none:
      return;
    case ShortcutMode::collinear:
      path.keep(collinear_keep(path.points));
      return;
    case ShortcutMode::turning_points:
      path.keep(collinear_keep(path.points));
      path.keep(turning_point_keep(grid, path.points, sight, poll));
      return;
    case ShortcutMode::greedy:
      // Collinear nodes first: same shortcuts through the corners, far fewer sight tests.
      path.keep(collinear_keep(path.points));
      path.keep(greedy_keep(grid, path.points, sight, false, poll));
      return;
    case ShortcutMode::forward: {
      std::vector<Point> refined = path.points;
      insert_midpoints(refined);
      path.replace(select_points(refined, forward_keep(grid, refined, sight, poll)));
      return;
    }
    case ShortcutMode::from_goal:
      path.keep(greedy_keep(grid, path.points, sight, true, poll));
      return;
    case ShortcutMode::direct_midpoint: {
      std::vector<Point> p = path.points;
      shortcut_direct_midpoint(grid, p, sight, poll);
      path.replace(std::move(p));
      return;
    }
  }
}

void apply_smoothing(const Grid& grid, const PostprocessOptions& options, const SightRule& sight,
                     WorkingPath& path, DeadlinePoller* poll) {
  switch (options.smoothing) {
    case SmoothingMode::none:
      return;
    case SmoothingMode::bezier:
      path.replace(bezier_corners(grid, path.points, sight, options.bezier, poll));
      return;
    case SmoothingMode::bspline:
      if (!path.kept.empty()) {
        path.replace(bspline_smooth(grid, path.dense, path.kept, sight, options.bspline, poll));
      } else {
        std::vector<int> all(path.points.size());
        for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
        path.replace(
            bspline_smooth(grid, path.points, std::move(all), sight, options.bspline, poll));
      }
      return;
  }
}

void fail_postprocessing(PlanResult& result, const char* step) {
  result.failure = Failure::limit;
  result.message = std::string("deadline passed during the ") + step;
  result.path.clear();
}

void finish_path(const Grid& grid, const PostprocessOptions& options, WorkingPath& path,
                 PlanResult& result, const Deadline& deadline) {
  result.extra.emplace_back("key_points", static_cast<double>(path.points.size()));
  result.waypoints_before_sampling = static_cast<std::int64_t>(path.points.size());
  if (options.smoothing != SmoothingMode::none) {
    PhaseTimer timer(result, "smoothing");
    DeadlinePoller poll = postprocess_poller(deadline);
    apply_smoothing(grid, options, sight_rule(result.rule, options.curve_clearance), path, &poll);
    if (poll.has_expired()) return fail_postprocessing(result, "smoothing");
  }
  result.path = std::move(path.points);
}

void apply_postprocessing(const Grid& grid, const PostprocessOptions& options, PlanResult& result,
                          const Deadline& deadline) {
  apply_postprocessing(grid, options, sight_rule(result.rule, options.shortcut_margin), result,
                       deadline);
}

void apply_postprocessing(const Grid& grid, const PostprocessOptions& options,
                          const SightRule& shortcut_sight, PlanResult& result,
                          const Deadline& deadline) {
  if (!result.ok()) return;
  if (options.shortcut == ShortcutMode::none && options.smoothing == SmoothingMode::none) return;
  WorkingPath path(std::move(result.path));
  if (options.shortcut != ShortcutMode::none) {
    PhaseTimer timer(result, "postprocess");
    DeadlinePoller poll = postprocess_poller(deadline);
    apply_shortcut(grid, options.shortcut, shortcut_sight, path, &poll);
    if (poll.has_expired()) return fail_postprocessing(result, "shortcut");
  }
  finish_path(grid, options, path, result, deadline);
}

}  // namespace agv
