#include "algos/search/grid_search_params.h"

#include <stdexcept>
#include <string>

namespace agv {

ParamSpec corner_rule_param(CornerRule default_rule) {
  return ParamSpec::choice(
      "corner_rule", std::string(to_string(default_rule)), {"allow", "no_squeeze", "no_corner_cut"},
      "diagonal move rule: allow = any diagonal to a free cell; no_squeeze = refused when both "
      "adjacent cardinal cells are blocked (paper 002); no_corner_cut = refused when either is "
      "blocked (paper 003, MovingAI)");
}

ParamSpec heuristic_param(Heuristic default_heuristic) {
  return ParamSpec::choice(
      "heuristic", std::string(to_string(default_heuristic)), heuristic_names(),
      "distance-to-goal estimate: euclidean, manhattan, chebyshev, octile (straight 1, diagonal "
      "diagonal_cost), octile_as_printed (paper 002 eq. 7 as printed: weights swapped), zero");
}

ParamSpec diagonal_cost_param(double default_cost) {
  return ParamSpec::number("diagonal_cost", default_cost, 1.0, 2.0,
                           "cost of a diagonal move (straight moves cost 1); paper 002 uses 1.4");
}

CornerRule corner_rule_of(const Params& params) {
  const auto rule = corner_rule_from_string(params.choice("corner_rule"));
  if (!rule) throw std::logic_error("corner_rule not validated");
  return *rule;
}

Heuristic heuristic_of(const Params& params) {
  const auto h = heuristic_from_string(params.choice("heuristic"));
  if (!h) throw std::logic_error("heuristic not validated");
  return *h;
}

GridSearchSetup grid_search_setup_of(const Params& params) {
  GridSearchSetup setup;
  setup.rule = corner_rule_of(params);
  setup.diagonal_cost = params.number("diagonal_cost");
  return setup;
}

}  // namespace agv
