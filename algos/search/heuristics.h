#pragma once
// Grid heuristics of docs/PLANNERS.md "Common ground": the distance estimate from a cell to the
// goal, from the absolute coordinate differences (dx, dy) in cells. Each is also a tiny functor
// type so the search core is instantiated per heuristic and the per-node call inlines to a few
// instructions (no switch per node); with_heuristic() turns the runtime choice into that type once
// per plan call.

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace agv {

inline constexpr double kSqrt2 = 1.41421356237309504880;

enum class Heuristic {
  euclidean,
  manhattan,
  chebyshev,
  octile,             // straight moves cost 1, diagonal moves diagonal_cost
  octile_as_printed,  // paper 002 eq. 7 as printed: diagonal count x 1, straight count x 1.4
  zero,               // Dijkstra
};

std::string_view to_string(Heuristic h);
std::optional<Heuristic> heuristic_from_string(std::string_view name);
// The names in declaration order (for ParamSpec choices).
const std::vector<std::string>& heuristic_names();

struct EuclideanHeuristic {
  double operator()(int dx, int dy) const {
    return std::sqrt(static_cast<double>(dx) * dx + static_cast<double>(dy) * dy);
  }
};
struct ManhattanHeuristic {
  double operator()(int dx, int dy) const { return static_cast<double>(dx + dy); }
};
struct ChebyshevHeuristic {
  double operator()(int dx, int dy) const { return static_cast<double>(std::max(dx, dy)); }
};
struct OctileHeuristic {
  double diagonal_cost = kSqrt2;
  double operator()(int dx, int dy) const {
    const int lo = std::min(dx, dy);
    const int hi = std::max(dx, dy);
    return diagonal_cost * lo + static_cast<double>(hi - lo);
  }
};
// Paper 002 eq. 7 as printed: the octile weights swapped, i.e. the min(dx, dy) diagonal steps
// weighted 1 and the |dx - dy| straight steps weighted by diagonal_cost. Kept so the misprint's
// cost can be measured (docs/PLANNERS.md); it is not admissible and not the paper's intent.
struct OctileAsPrintedHeuristic {
  double diagonal_cost = kSqrt2;
  double operator()(int dx, int dy) const {
    const int lo = std::min(dx, dy);
    const int hi = std::max(dx, dy);
    return static_cast<double>(lo) + diagonal_cost * (hi - lo);
  }
};
struct ZeroHeuristic {
  double operator()(int, int) const { return 0.0; }
};

// Value of `h` for coordinate differences (signs ignored).
double heuristic_value(Heuristic h, double dx, double dy, double diagonal_cost);

// Calls f(functor) with the functor type of `h`; returns what f returns. One dispatch per plan
// call, so the search loop is compiled once per heuristic.
template <class F>
decltype(auto) with_heuristic(Heuristic h, double diagonal_cost, F&& f) {
  switch (h) {
    case Heuristic::manhattan:
      return f(ManhattanHeuristic{});
    case Heuristic::chebyshev:
      return f(ChebyshevHeuristic{});
    case Heuristic::octile:
      return f(OctileHeuristic{diagonal_cost});
    case Heuristic::octile_as_printed:
      return f(OctileAsPrintedHeuristic{diagonal_cost});
    case Heuristic::zero:
      return f(ZeroHeuristic{});
    case Heuristic::euclidean:
      break;
  }
  return f(EuclideanHeuristic{});
}

}  // namespace agv
