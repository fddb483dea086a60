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
//   to the earliest node it sees under SightRule::margin(shortcut_margin) (obstacle centres at
//   least shortcut_margin + 0.5 from the segment; paper: the distance to the centre point must
//   exceed the safety distance, one cell edge, so the default 0.5): the pipeline's `from_goal`
//   shortcut;
// - clamped cubic uniform B-spline (section 2.4, appendix A), the remaining nodes as control
//   points, refitted by re-inserting removed cells where it would hit (`smoothing: bspline`).
// Work counters: grid_search_counters() (docs/METRICS.md "Work counters"). Extra metric
// generated_nodes: cells put on the open list (the paper's "searched child nodes"), counted by
// the search listener.

#include <array>
#include <cmath>
#include <memory>

#include "algos/postprocess/postprocess_params.h"
#include "algos/search/grid_search_params.h"
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

// Counts the cells the search puts on the open list, the source included: the "searched
// children" of paper 004's Figure 6 (gray cells), which the five-direction rule reduces.
struct GeneratedCounter {
  void generated(int /*index*/) { ++count; }
  void expanded(int /*index*/, double /*g*/) {}
  void relaxed(int /*index*/, double /*g*/, double /*key*/) {}
  std::int64_t count = 0;
};

enum class Directions { five, eight };

struct KinAStarOptions {
  GridSearchOptions search;
  Directions directions = Directions::five;
  double weight_base = 1.5;
  PostprocessOptions post;  // section 2.3: from_goal under shortcut_margin; 2.4: smoothing
};

ParamDecls<KinAStarOptions> kin_astar_decls() {
  ParamDecls<KinAStarOptions> d;
  d.include(&KinAStarOptions::search, grid_search_decls(CornerRule::no_corner_cut, std::nullopt))
      .choice("directions", &KinAStarOptions::directions, Directions::five,
              ChoiceTable<Directions>{{"five", Directions::five}, {"eight", Directions::eight}},
              "five = Table 1's five directions toward the goal where the 3x3 neighbourhood is "
              "free (all 8 elsewhere); eight = always all 8")
      .number("weight_base", &KinAStarOptions::weight_base, 1.5, 0.0, 10.0,
              "the 1.5 of f = g + (1.5 + r/R) h (section 2.2)")
      // Paper 004 section 2.3: the distance from the obstacle's centre point must exceed the
      // safety distance, one cell edge; margin m keeps centres m + 0.5 away, so 0.5.
      .include(&KinAStarOptions::post, shortcut_margin_decls(0.5))
      .include(&KinAStarOptions::post, smoothing_decls(SmoothingMode::bspline));
  return d;
}

class KinAStarPlanner final : public Planner {
 public:
  explicit KinAStarPlanner(const KinAStarOptions& options) : o_(options) {
    o_.post.shortcut = ShortcutMode::from_goal;  // section 2.3
  }

  PlanResult plan(const PlanRequest& request) const override {
    KinAStarPolicy policy;
    policy.goal_cell = request.goal;
    policy.weight_base = o_.weight_base;
    policy.five = o_.directions == Directions::five;
    const double big_r = std::hypot(static_cast<double>(request.goal.x - request.start.x),
                                    static_cast<double>(request.goal.y - request.start.y));
    policy.inverse_R = big_r > 0.0 ? 1.0 / big_r : 0.0;
    GeneratedCounter generated;
    PlanResult result = plan_grid_search(request, o_.search.setup, policy, generated);
    if (result.failure != Failure::invalid_input)
      result.extra.emplace_back("generated_nodes", static_cast<double>(generated.count));
    // Section 2.3, then 2.4 (B-spline). The safety distance is a margin test even at 0.
    apply_postprocessing(request.grid, o_.post,
                         SightRule::margin(o_.post.shortcut_margin, o_.search.setup.rule), result,
                         request.deadline);
    return result;
  }

 private:
  KinAStarOptions o_;
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
  info.summary =
      "paper 004 kinematic-constraint A*: five-direction search in open areas, "
      "weighted heuristic (1.5 + r/R), redundancy removal with a safety distance, "
      "clamped cubic B-spline";
  info.source = "paper 004 section 2 (eq. 1, Table 1, appendix A); docs/PLANNERS.md";
  info.counters = grid_search_counters();
  info.params = kin_astar_decls().specs();
  info.make = [](const Params& params) -> std::unique_ptr<Planner> {
    return std::make_unique<KinAStarPlanner>(kin_astar_decls().read(params));
  };
  return info;
}

}  // namespace agv
