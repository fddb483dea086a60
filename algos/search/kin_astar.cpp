#include "algos/search/kin_astar.h"

// A policy of the one search core (algos/search/search_core.h) plus paper 004's post-processing:
// - five-direction search (section 2.1, eq. 1, Table 1): where the node's 3x3 neighbourhood is
//   obstacle-free, only the five directions within 90 degrees of the goal's sector are expanded
//   (direction_mask hook); elsewhere all 8. `directions: eight` turns the rule off, for the
//   paired comparison of the paper's Figure 6;
// - weighted heuristic (section 2.2): f = g + (1.5 + r / R) * h, h = r = Euclidean distance to the
//   goal, R = start-goal distance (`weight_base` = the 1.5);
// - child nodes: `corner_rule: no_corner_cut`;
// - secondary redundancy removal (section 2.3): greedy from the goal backwards, each node joined
//   to the earliest node it sees under SightRule::margin(d_safe) (obstacle centres at least
//   d_safe + 0.5 from the segment; paper: the safety distance is one cell edge);
// - clamped cubic uniform B-spline (section 2.4, appendix A), the remaining nodes as control
//   points, refitted by re-inserting removed cells where it would hit (`smoothing: bspline`).
// expanded_nodes: cells taken off the open list and closed (the goal included). Extra metric
// generated_nodes: cells put on the open list (the paper's "searched child nodes").

#include <array>
#include <cmath>
#include <memory>

#include "algos/search/grid_search_params.h"
#include "algos/postprocess/path_simplify.h"
#include "algos/postprocess/postprocess_params.h"
#include "algos/search/search_core.h"

namespace agv {

namespace {

// Direction (corner_rule.h numbering) at each 45-degree step of atan2 in grid coordinates
// (x right, y down): E, SE, S, SW, W, NW, N, NE.
constexpr std::array<int, 8> kDirectionAtAngle = {0, 4, 1, 5, 2, 6, 3, 7};

constexpr std::array<std::uint8_t, 8> make_sector_masks() {
  std::array<std::uint8_t, 8> masks{};
  for (int s = 0; s < 8; ++s) {
    unsigned m = 0;
    for (int k = -2; k <= 2; ++k) m |= 1U << kDirectionAtAngle[(s + k + 8) % 8];
    masks[s] = static_cast<std::uint8_t>(m);
  }
  return masks;
}
constexpr std::array<std::uint8_t, 8> kSectorMasks = make_sector_masks();

// tan(22.5 degrees): sector boundaries. Integer offsets never lie exactly on one (irrational).
constexpr double kTan22_5 = 0.41421356237309504880;

struct KinAStarPolicy : PolicyDefaults {
  // Section 2.2: (weight_base + r / R) * h with r = h.
  double heuristic(int x, int y, int /*index*/) const {
    const double h =
        std::hypot(static_cast<double>(goal_cell.x - x), static_cast<double>(goal_cell.y - y));
    return (weight_base + h * inverse_R) * h;
  }
  std::uint8_t direction_mask(int x, int y, int /*index*/, std::uint8_t free_mask) const {
    if (!five || free_mask != 0xFF) return 0xFF;  // Table 1 applies only to an open 3x3
    return five_direction_mask(goal_cell.x - x, goal_cell.y - y);
  }
  Cell goal_cell;
  double weight_base = 1.5;
  double inverse_R = 0.0;
  bool five = true;
};

// Cells the last search put on the open list (open or closed when it stopped): the "searched
// children" of paper 004's Figure 6 (gray cells), which the five-direction rule reduces.
std::int64_t seen_cells(const PlanRequest& request) {
  GridSearchBuffers& buffers = request.scratch.get<GridSearchBuffers>();
  const std::uint8_t* stamp = buffers.stamps();
  const std::uint8_t open = buffers.open_stamp(), closed = buffers.closed_stamp();
  std::int64_t seen = 0;
  for (int i = 0; i < request.grid.padded_size(); ++i)
    seen += (stamp[i] == open || stamp[i] == closed) ? 1 : 0;
  return seen;
}

class KinAStarPlanner final : public Planner {
 public:
  explicit KinAStarPlanner(const Params& params)
      : setup_(grid_search_setup_of(params)),
        five_(params.choice("directions") == "five"),
        weight_base_(params.number("weight_base")),
        d_safe_(params.number("d_safe")) {
    read_smoothing_params(params, post_);
  }

  PlanResult plan(const PlanRequest& request) const override {
    KinAStarPolicy policy;
    policy.goal_cell = request.goal;
    policy.weight_base = weight_base_;
    policy.five = five_;
    const double big_r = std::hypot(static_cast<double>(request.goal.x - request.start.x),
                                    static_cast<double>(request.goal.y - request.start.y));
    policy.inverse_R = big_r > 0.0 ? 1.0 / big_r : 0.0;
    PlanResult result = plan_grid_search(request, setup_, policy);
    if (result.failure != Failure::invalid_input)
      result.extra.emplace_back("generated_nodes", static_cast<double>(seen_cells(request)));
    if (!result.ok()) return result;
    WorkingPath path(std::move(result.path));
    {
      PhaseTimer timer(result, "postprocess");  // section 2.3
      path.keep(greedy_keep(request.grid, path.points, SightRule::margin(d_safe_, setup_.rule),
                            /*from_goal=*/true));
    }
    finish_path(request.grid, post_, path, result);  // section 2.4: B-spline
    return result;
  }

 private:
  GridSearchSetup setup_;
  bool five_;
  double weight_base_;
  double d_safe_;
  PostprocessOptions post_;
};

}  // namespace

std::uint8_t five_direction_mask(int dx, int dy) {
  const double ax = std::abs(dx), ay = std::abs(dy);
  int sector;
  if (ay <= kTan22_5 * ax) {
    sector = dx >= 0 ? 0 : 4;  // E / W
  } else if (ax <= kTan22_5 * ay) {
    sector = dy > 0 ? 2 : 6;  // S / N (y down)
  } else {
    sector = dx > 0 ? (dy > 0 ? 1 : 7) : (dy > 0 ? 3 : 5);  // SE, NE, SW, NW
  }
  return kSectorMasks[sector];
}

PlannerInfo kin_astar_planner() {
  PlannerInfo info;
  info.name = "kin_astar";
  info.summary = "paper 004 kinematic-constraint A*: five-direction search in open areas, "
                 "weighted heuristic (1.5 + r/R), redundancy removal with a safety distance, "
                 "clamped cubic B-spline";
  info.source = "paper 004 section 2 (eq. 1, Table 1, appendix A); PLANNERS.md";
  info.expanded_nodes_meaning = "cells taken off the open list and closed (goal included)";
  info.params = {
      corner_rule_param(CornerRule::no_corner_cut),
      diagonal_cost_param(),
      ParamSpec::choice("directions", "five", {"five", "eight"},
                        "five = Table 1's five directions toward the goal where the 3x3 "
                        "neighbourhood is free (all 8 elsewhere); eight = always all 8"),
      ParamSpec::number("weight_base", 1.5, 0.0, 10.0,
                        "the 1.5 of f = g + (1.5 + r/R) h (section 2.2)"),
      ParamSpec::number("d_safe", 1.0, 0.0, 5.0,
                        "safety distance of the redundancy removal, cells: obstacle centres at "
                        "least d_safe + 0.5 from a shortcut segment (paper: one cell edge)"),
  };
  for (auto& spec : smoothing_params(SmoothingMode::bspline)) info.params.push_back(std::move(spec));
  info.make = [](const Params& params) -> std::unique_ptr<Planner> {
    return std::make_unique<KinAStarPlanner>(params);
  };
  return info;
}

}  // namespace agv
