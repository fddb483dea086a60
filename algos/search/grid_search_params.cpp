#include "algos/search/grid_search_params.h"

#include <stdexcept>
#include <string>

namespace agv {

namespace {

const char* const kCornerRuleDoc =
    "diagonal move rule: allow = any diagonal to a free cell; no_squeeze = refused when both "
    "adjacent cardinal cells are blocked (paper 002); no_corner_cut = refused when either is "
    "blocked (paper 003, MovingAI)";

const ChoiceTable<CornerRule>& corner_rules() {
  static const ChoiceTable<CornerRule> table = {{"allow", CornerRule::allow},
                                                {"no_squeeze", CornerRule::no_squeeze},
                                                {"no_corner_cut", CornerRule::no_corner_cut}};
  return table;
}

ChoiceTable<Heuristic> heuristics() {
  ChoiceTable<Heuristic> table;
  for (const std::string& name : heuristic_names())
    table.emplace_back(name, *heuristic_from_string(name));
  return table;
}

}  // namespace

ParamDecls<GridSearchOptions> grid_search_decls(CornerRule default_rule,
                                                std::optional<Heuristic> default_heuristic,
                                                double default_diagonal_cost) {
  ParamDecls<GridSearchOptions> d;
  d.choice(
      "corner_rule", [](GridSearchOptions& o) -> CornerRule& { return o.setup.rule; }, default_rule,
      corner_rules(), kCornerRuleDoc);
  if (default_heuristic)
    d.choice("heuristic", &GridSearchOptions::heuristic, *default_heuristic, heuristics(),
             "distance-to-goal estimate: euclidean, manhattan, chebyshev, octile (straight 1, "
             "diagonal diagonal_cost), octile_as_printed (paper 002 eq. 7 as printed: weights "
             "swapped), zero");
  d.number(
      "diagonal_cost", [](GridSearchOptions& o) -> double& { return o.setup.diagonal_cost; },
      default_diagonal_cost, 1.0, 2.0,
      "cost of a diagonal move (straight moves cost 1); paper 002 uses 1.4");
  return d;
}

ParamDecls<CornerRule> corner_rule_decls(CornerRule default_rule) {
  ParamDecls<CornerRule> d;
  d.choice(
      "corner_rule", [](CornerRule& rule) -> CornerRule& { return rule; }, default_rule,
      corner_rules(), kCornerRuleDoc);
  return d;
}

}  // namespace agv
