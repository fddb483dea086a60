#pragma once
// HMA*, the Hybrid Modified A* of paper 000 section 5 (docs/PLANNERS.md "HMA*"): the MA* path's key
// nodes, then a particle swarm with stochastic inertia weight re-placing the middle node of each
// sliding window (P(n), P(n+2)).

#include <optional>
#include <string_view>

#include "algos/planner_info.h"

namespace agv {

PlannerInfo hma_star_planner();

// The PSO inertia weight of iteration j (1..t_max), option `inertia`.
enum class Inertia {
  stochastic,  // paper 000 eq. 5.1d: w_max - (w_max - w_min) (j / t_max) e^rho
  adaptive,    // paper 000 eq. 5.1c as printed: (w_max + w_min) (gbest_j / gbest_j-1) - w_max j /
               // t_max
  linear,      // eq. 5.1d with rho = 0, the linear decrease it is derived from
};
std::optional<Inertia> inertia_from_string(std::string_view name);

struct InertiaInputs {
  int j = 1;  // iteration, 1..t_max
  int t_max = 1;
  double w_max = 0.9;
  double w_min = 0.4;
  double rho = 0.0;  // stochastic: uniform in [-0.1, 0.1], drawn once per iteration
  // adaptive: the best cost (path length, +inf while no particle is feasible) after iterations
  // j and j - 1; the ratio is taken as 1 when either is not finite or j == 1.
  double gbest = 0.0;
  double gbest_previous = 0.0;
};
double inertia_weight(Inertia mode, const InertiaInputs& in);

}  // namespace agv
