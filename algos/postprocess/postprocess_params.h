#pragma once
// Post-processing any grid planner can apply through its parameters (issue 3), so a user can run
// classic A* + B-spline as easily as the papers' own pipelines. The steps themselves live in
// algos/postprocess/path_simplify.h and algos/postprocess/path_curves.h (one implementation each);
// this file only names them as parameters and chains them:
//
//   search path (cell centres) -> shortcut (`shortcut`, under `shortcut_margin`)
//                              -> smoothing (`smoothing`: none | bezier | bspline)
//
// Every step tests collisions with the planner's own corner rule (SightRule::cells(rule), or
// SightRule::margin(d, rule)), so the result validates under the rule the planner reports.

#include <string>
#include <vector>

#include "algos/planner.h"
#include "algos/postprocess/path_curves.h"
#include "core/corner_rule.h"
#include "core/grid.h"
#include "core/line_of_sight.h"
#include "core/params.h"

namespace agv {

enum class ShortcutMode {
  none,
  collinear,        // collinear removal only (paper 000 step 2)
  turning_points,   // collinear + turning-point removal (paper 000 step 3)
  greedy,           // collinear + farthest-visible greedy shortcut
  forward,          // paper 002 forward key-point search on the midpoint-refined path
  from_goal,        // paper 004 secondary redundancy removal (greedy from the goal)
  direct_midpoint,  // paper 003 direct and midpoint shortcuts
};
enum class SmoothingMode { none, bezier, bspline };

struct PostprocessOptions {
  ShortcutMode shortcut = ShortcutMode::none;
  double shortcut_margin = 0.0;  // cells; 0 = SightRule::cells
  SmoothingMode smoothing = SmoothingMode::none;
  // cells; 0 = SightRule::cells. Follows the sweep's collision-model clearance (algos/registry.h):
  // the curve keeps what the path is judged under, the shortcut keeps the planner's own margin.
  double curve_clearance = 0.0;
  BezierOptions bezier;
  BsplineOptions bspline;
};

// `shortcut`, then `shortcut_margin` (default 0).
ParamDecls<PostprocessOptions> shortcut_decls(ShortcutMode default_mode);
// `shortcut_margin` alone, for a variant whose paper fixes the shortcut mode (alt_astar: 0,
// kin_astar: 1, paper 004's one-cell safety distance) and keeps only its clearance a parameter.
ParamDecls<PostprocessOptions> shortcut_margin_decls(double default_margin);
// `smoothing`, `curve_step`, `bezier_distance`, `bezier_points`, `curve_clearance`.
ParamDecls<PostprocessOptions> smoothing_decls(SmoothingMode default_mode);

// The collision rule of a step: cells under the corner rule, or that plus a margin in cells.
SightRule sight_rule(CornerRule rule, double margin);

// A polyline in the making. While it is a subsequence of `dense` (the search's cell path),
// `kept` holds its indices, so the B-spline refit can re-insert removed cells; a step that moves
// or adds points clears `kept` and the polyline stands alone.
struct WorkingPath {
  std::vector<Point> dense;
  std::vector<int> kept;
  std::vector<Point> points;

  explicit WorkingPath(std::vector<Point> path);
  // Keeps points[local[0]], points[local[1]], ... (indices into `points`).
  void keep(const std::vector<int>& local);
  // Replaces the polyline by free-standing points.
  void replace(std::vector<Point> path);
};

// `poll`: the steps' deadline (path_simplify.h, path_curves.h); an expired one leaves `path`
// unfinished, for the caller to discard.
void apply_shortcut(const Grid& grid, ShortcutMode mode, const SightRule& sight, WorkingPath& path,
                    DeadlinePoller* poll = nullptr);
// `sight`: the rule the curve must be free under (the planner's cells rule).
void apply_smoothing(const Grid& grid, const PostprocessOptions& options, const SightRule& sight,
                     WorkingPath& path, DeadlinePoller* poll = nullptr);

// Sight tests (or points, corners) between two polls of the deadline in post-processing.
inline constexpr std::int64_t kPostprocessPollInterval = 16;
// A poller of the plan's deadline for post-processing steps.
inline DeadlinePoller postprocess_poller(const Deadline& deadline) {
  return DeadlinePoller(deadline, kPostprocessPollInterval);
}
// Makes `result` the limit failure of a plan whose post-processing step `step` the deadline cut.
void fail_postprocessing(PlanResult& result, const char* step);

// The last step of every pipeline: records the waypoint count before curve sampling as the extra
// metric "key_points", applies the smoothing (phase "smoothing") under the result's corner rule
// and `curve_clearance`, and moves the polyline into result.path. A deadline that expires during
// the smoothing makes the result a limit failure.
void finish_path(const Grid& grid, const PostprocessOptions& options, WorkingPath& path,
                 PlanResult& result, const Deadline& deadline);

// Both steps on a successful search result, under its corner rule, timed as the phases
// "postprocess" (shortcut) and "smoothing"; a failed result, or options that ask for nothing,
// leave the result alone. The shortcut tests sight under sight_rule(rule, shortcut_margin).
// Both steps poll `deadline` (the plan's): when it expires the result is a limit failure.
void apply_postprocessing(const Grid& grid, const PostprocessOptions& options, PlanResult& result,
                          const Deadline& deadline);
// The same with the shortcut's sight test given: a paper's own clearance rule (MA*'s obstacle
// circles of radius r_obs, paper 000 eq. 5.1b). The smoothing still tests under the cells rule.
void apply_postprocessing(const Grid& grid, const PostprocessOptions& options,
                          const SightRule& shortcut_sight, PlanResult& result,
                          const Deadline& deadline);

}  // namespace agv
