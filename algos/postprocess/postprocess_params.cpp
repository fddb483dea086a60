#include "algos/postprocess/postprocess_params.h"

#include <stdexcept>
#include <utility>

#include "algos/postprocess/path_simplify.h"

namespace agv {

namespace {

const std::vector<std::string>& shortcut_names() {
  static const std::vector<std::string> names = {
      "none", "collinear", "turning_points", "greedy", "forward", "from_goal", "direct_midpoint"};
  return names;
}
const std::vector<std::string>& smoothing_names() {
  static const std::vector<std::string> names = {"none", "bezier", "bspline"};
  return names;
}

template <class E>
E enum_of(const std::vector<std::string>& names, const std::string& value) {
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == value) return static_cast<E>(i);
  throw std::logic_error("post-processing parameter not validated: " + value);
}

}  // namespace

std::vector<ParamSpec> shortcut_params(ShortcutMode default_mode) {
  return {
      ParamSpec::choice(
          "shortcut", shortcut_names()[static_cast<std::size_t>(default_mode)], shortcut_names(),
          "path shortcut after the search: none; collinear (drop straight-through nodes); "
          "turning_points (paper 000 step 3: drop a turning point whose neighbours see each "
          "other, repeated); greedy (jump to the farthest node in sight); forward (paper 002: "
          "midpoints inserted, then forward key-point search); from_goal (paper 004: greedy from "
          "the goal); direct_midpoint (paper 003: direct, else midpoint shortcut). Never longer "
          "than the search path"),
      ParamSpec::number("shortcut_margin", 0.0, 0.0, 10.0,
                        "clearance the shortcut segments keep, in cells: every obstacle centre "
                        "at least margin + 0.5 away (0 = the segment touches no obstacle cell)"),
  };
}

std::vector<ParamSpec> smoothing_params(SmoothingMode default_mode) {
  return {
      ParamSpec::choice("smoothing", smoothing_names()[static_cast<std::size_t>(default_mode)],
                        smoothing_names(),
                        "curve fitting after the shortcut: none; bezier (paper 002 eq. 14: a "
                        "quadratic Bezier at each corner, shrunk on collision); bspline (paper "
                        "004: clamped cubic uniform B-spline through the nodes as control "
                        "points, refitted on collision). Output: the curve's samples"),
      ParamSpec::number("curve_step", 0.1, 0.01, 1.0,
                        "B-spline sample spacing in cells (the curve is returned as samples)"),
      ParamSpec::number("bezier_distance", 1.0, 0.05, 10.0,
                        "Bezier: distance L of the control points P0, P2 from the corner, cells "
                        "(clamped to half of each adjacent segment; paper 002: one cell)"),
      ParamSpec::integer("bezier_points", 10, 2, 1000,
                         "Bezier: samples per corner curve, its two ends included"),
  };
}

void read_shortcut_params(const Params& params, PostprocessOptions& options) {
  options.shortcut = enum_of<ShortcutMode>(shortcut_names(), params.choice("shortcut"));
  options.shortcut_margin = params.number("shortcut_margin");
}

void read_smoothing_params(const Params& params, PostprocessOptions& options) {
  options.smoothing = enum_of<SmoothingMode>(smoothing_names(), params.choice("smoothing"));
  options.bspline.sample_step = params.number("curve_step");
  options.bezier.corner_distance = params.number("bezier_distance");
  options.bezier.points_per_curve = static_cast<int>(params.integer("bezier_points"));
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

void apply_shortcut(const Grid& grid, ShortcutMode mode, const SightRule& sight,
                    WorkingPath& path) {
  switch (mode) {
    case ShortcutMode::none:
      return;
    case ShortcutMode::collinear:
      path.keep(collinear_keep(path.points));
      return;
    case ShortcutMode::turning_points:
      path.keep(collinear_keep(path.points));
      path.keep(turning_point_keep(grid, path.points, sight));
      return;
    case ShortcutMode::greedy:
      // Collinear nodes first: same shortcuts through the corners, far fewer sight tests.
      path.keep(collinear_keep(path.points));
      path.keep(greedy_keep(grid, path.points, sight, false));
      return;
    case ShortcutMode::forward: {
      std::vector<Point> refined = path.points;
      insert_midpoints(refined);
      path.replace(select_points(refined, forward_keep(grid, refined, sight)));
      return;
    }
    case ShortcutMode::from_goal:
      path.keep(greedy_keep(grid, path.points, sight, true));
      return;
    case ShortcutMode::direct_midpoint: {
      std::vector<Point> p = path.points;
      shortcut_direct_midpoint(grid, p, sight);
      path.replace(std::move(p));
      return;
    }
  }
}

void apply_smoothing(const Grid& grid, const PostprocessOptions& options, const SightRule& sight,
                     WorkingPath& path) {
  switch (options.smoothing) {
    case SmoothingMode::none:
      return;
    case SmoothingMode::bezier:
      path.replace(bezier_corners(grid, path.points, sight, options.bezier));
      return;
    case SmoothingMode::bspline:
      if (!path.kept.empty()) {
        path.replace(bspline_smooth(grid, path.dense, path.kept, sight, options.bspline));
      } else {
        std::vector<int> all(path.points.size());
        for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
        path.replace(bspline_smooth(grid, path.points, std::move(all), sight, options.bspline));
      }
      return;
  }
}

void finish_path(const Grid& grid, const PostprocessOptions& options, WorkingPath& path,
                 PlanResult& result) {
  result.extra.emplace_back("key_points", static_cast<double>(path.points.size()));
  result.waypoints_before_sampling = static_cast<std::int64_t>(path.points.size());
  if (options.smoothing != SmoothingMode::none) {
    PhaseTimer timer(result, "smoothing");
    apply_smoothing(grid, options, SightRule::cells(result.rule), path);
  }
  result.path = std::move(path.points);
}

void apply_postprocessing(const Grid& grid, const PostprocessOptions& options, PlanResult& result) {
  if (!result.ok()) return;
  if (options.shortcut == ShortcutMode::none && options.smoothing == SmoothingMode::none) return;
  WorkingPath path(std::move(result.path));
  if (options.shortcut != ShortcutMode::none) {
    PhaseTimer timer(result, "postprocess");
    apply_shortcut(grid, options.shortcut, sight_rule(result.rule, options.shortcut_margin), path);
  }
  finish_path(grid, options, path, result);
}

}  // namespace agv
