#include "algos/search/heuristics.h"

namespace agv {

namespace {
constexpr Heuristic kAll[] = {Heuristic::euclidean,         Heuristic::manhattan,
                              Heuristic::chebyshev,         Heuristic::octile,
                              Heuristic::octile_as_printed, Heuristic::zero};
}  // namespace

std::string_view to_string(Heuristic h) {
  switch (h) {
    case Heuristic::euclidean:
      return "euclidean";
    case Heuristic::manhattan:
      return "manhattan";
    case Heuristic::chebyshev:
      return "chebyshev";
    case Heuristic::octile:
      return "octile";
    case Heuristic::octile_as_printed:
      return "octile_as_printed";
    case Heuristic::zero:
      return "zero";
  }
  return "euclidean";
}

std::optional<Heuristic> heuristic_from_string(std::string_view name) {
  for (Heuristic h : kAll)
    if (to_string(h) == name) return h;
  return std::nullopt;
}

const std::vector<std::string>& heuristic_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (Heuristic h : kAll) out.emplace_back(to_string(h));
    return out;
  }();
  return names;
}

double heuristic_value(Heuristic h, double dx, double dy, double diagonal_cost) {
  dx = std::abs(dx);
  dy = std::abs(dy);
  const double lo = std::min(dx, dy);
  const double hi = std::max(dx, dy);
  switch (h) {
    case Heuristic::euclidean:
      return std::sqrt(dx * dx + dy * dy);
    case Heuristic::manhattan:
      return dx + dy;
    case Heuristic::chebyshev:
      return hi;
    case Heuristic::octile:
      return diagonal_cost * lo + (hi - lo);
    case Heuristic::octile_as_printed:
      return lo + diagonal_cost * (hi - lo);
    case Heuristic::zero:
      return 0.0;
  }
  return 0.0;
}

}  // namespace agv
