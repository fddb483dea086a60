#include "generators/map_generators.h"

// Common to all generators: the density base M is the number of cells that may hold obstacles
// (all W*H cells, minus the two reserved endpoint cells in `corners` mode) and the target
// obstacle count is T = round(density * M); what each generator does with T is in its own file.
//
// Endpoints: `corners` = (0, H-1) -> (W-1, 0), reserved free before the map is drawn.
// `random` = two distinct free cells drawn uniformly, redrawn (up to kEndpointTries pairs) until
// their centres are at least min_distance apart; a map where that fails counts as a rejection.
// `fixed` = spec.start -> spec.goal, reserved free like the corners; a generator that blocks a
// reserved cell anyway (maze walls, room walls) has its map rejected and redrawn, the endpoints
// never move.
// require_solvable: a map whose endpoints do not connect under solvable_rule is rejected and a
// new one drawn from the same Rng; after max_attempts maps, std::runtime_error.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "core/connectivity.h"
#include "core/input_error.h"
#include "core/str_cat.h"
#include "generators/canvas.h"
#include "generators/registry.h"

namespace agv {
namespace {

constexpr int kMinSide = 2;
constexpr int kEndpointTries = 1000;

// The common map options; then the generator and its shape parameters, through the registry's
// one declaration of each (so make_map and config loading cannot disagree on a range).
Params validate(const MapSpec& s, const GeneratorInfo*& info) {
  info = find_generator(s.generator);
  if (info == nullptr) {
    std::string known;
    for (const auto& g : generator_registry()) known += (known.empty() ? "" : ", ") + g.name;
    throw std::invalid_argument(str_cat("generator: '", s.generator, "' is not one of ", known));
  }
  if (s.width < kMinSide || s.width > kMaxMapSide) {
    throw std::invalid_argument(str_cat("width: ", s.width, " is outside [2, ", kMaxMapSide, "]"));
  }
  if (s.height < kMinSide || s.height > kMaxMapSide) {
    throw std::invalid_argument(
        str_cat("height: ", s.height, " is outside [2, ", kMaxMapSide, "]"));
  }
  if (!(s.density >= 0.0 && s.density < 1.0)) {
    throw std::invalid_argument(str_cat("density: ", s.density, " is outside [0, 1)"));
  }
  if (!(s.cell_edge > 0.0 && std::isfinite(s.cell_edge))) {
    throw std::invalid_argument(
        str_cat("cell_edge: ", s.cell_edge, " must be positive and finite"));
  }
  const double diagonal = std::hypot(s.width - 1.0, s.height - 1.0);
  if (!(s.min_distance >= 0.0 && s.min_distance <= diagonal)) {
    throw std::invalid_argument(str_cat("min_distance: ", s.min_distance, " is outside [0, ",
                                        diagonal, "] (the ", s.width, "x", s.height,
                                        " grid's corner-to-corner distance)"));
  }
  if (s.endpoints == EndpointMode::fixed) {
    const auto outside = [&](const Cell& c) {
      return c.x < 0 || c.y < 0 || c.x >= s.width || c.y >= s.height;
    };
    for (const auto& [name, c] : {std::pair{"start", s.start}, std::pair{"goal", s.goal}}) {
      if (outside(c)) {
        throw std::invalid_argument(str_cat(
            name, ": [", c.x, ", ", c.y, "] is outside the ", s.width, "x", s.height,
            " grid (0-based cells: x in [0, ", s.width - 1, "], y in [0, ", s.height - 1, "])"));
      }
    }
    if (s.start == s.goal) {
      throw std::invalid_argument(
          str_cat("goal: [", s.goal.x, ", ", s.goal.y, "] is the start cell (they must differ)"));
    }
  }
  if (s.max_attempts < 1) {
    throw std::invalid_argument(str_cat("max_attempts: ", s.max_attempts, " must be at least 1"));
  }
  try {
    return resolve_generator_params(*info, s.params, "params", s.width, s.height);
  } catch (const InputError& e) {
    throw std::invalid_argument(e.what());
  }
}

// Two distinct free cells with centres at least min_distance apart, or false.
bool draw_random_endpoints(MapContext& ctx, double min_distance, Cell& start, Cell& goal) {
  const Canvas& c = ctx.canvas;
  auto& free = ctx.pool;
  free.clear();
  for (int y = 0; y < c.height(); ++y) {
    for (int x = 0; x < c.width(); ++x) {
      if (!c.blocked(x, y)) free.push_back(y * c.width() + x);
    }
  }
  if (free.size() < 2) return false;
  const double min_sq = min_distance * min_distance;
  const auto n = static_cast<std::uint32_t>(free.size());
  for (int t = 0; t < kEndpointTries; ++t) {
    const int a = free[ctx.rng.below(n)];
    const int b = free[ctx.rng.below(n)];
    if (a == b) continue;
    const std::int64_t dx = a % c.width() - b % c.width();
    const std::int64_t dy = a / c.width() - b / c.width();
    if (static_cast<double>(dx * dx + dy * dy) >= min_sq) {
      start = {a % c.width(), a / c.width()};
      goal = {b % c.width(), b / c.width()};
      return true;
    }
  }
  return false;
}

}  // namespace

void check_map_spec(const MapSpec& spec) {
  const GeneratorInfo* info = nullptr;
  validate(spec, info);
}

MapInstance make_map(const MapSpec& spec, Rng& rng) {
  const GeneratorInfo* info = nullptr;
  const Params shape = validate(spec, info);
  Canvas canvas;
  canvas.reset(spec.width, spec.height, false);
  std::vector<int> pool;
  MapContext ctx{spec.width, spec.height, rng, canvas, {}, 0, pool};
  const bool fixed = spec.endpoints == EndpointMode::fixed;
  const Cell corner_start = fixed ? spec.start : Cell{0, spec.height - 1};
  const Cell corner_goal = fixed ? spec.goal : Cell{spec.width - 1, 0};
  const bool corners = spec.endpoints != EndpointMode::random;  // corners or fixed: reserved
  if (corners) {
    const int a = canvas.index(corner_start.x, corner_start.y);
    const int b = canvas.index(corner_goal.x, corner_goal.y);
    ctx.reserved = {std::min(a, b), std::max(a, b)};  // ascending
  }
  const std::int64_t m =
      static_cast<std::int64_t>(spec.width) * spec.height - std::ssize(ctx.reserved);
  ctx.target = std::llround(spec.density * static_cast<double>(m));

  ConnectivityScratch scratch;
  bool endpoints_failed = false;
  int blocked_maps = 0;  // fixed endpoints a generator blocked anyway
  for (int attempt = 0; attempt < spec.max_attempts; ++attempt) {
    info->generate(shape, ctx);
    Cell start = corner_start;
    Cell goal = corner_goal;
    if (fixed && (canvas.blocked(start.x, start.y) || canvas.blocked(goal.x, goal.y))) {
      ++blocked_maps;
      continue;
    }
    if (!corners && !draw_random_endpoints(ctx, spec.min_distance, start, goal)) {
      endpoints_failed = true;
      continue;
    }
    endpoints_failed = false;
    if (spec.require_solvable &&
        !connected(canvas.data(), canvas.stride(), canvas.padded_size(),
                   canvas.index(start.x, start.y), canvas.index(goal.x, goal.y), spec.solvable_rule,
                   scratch)) {
      continue;
    }
    MapInstance out{Grid(spec.width, spec.height, spec.cell_edge), start, goal, attempt};
    for (int y = 0; y < spec.height; ++y) {
      for (int x = 0; x < spec.width; ++x) {
        if (canvas.blocked(x, y)) out.grid.set_blocked(x, y, true);
      }
    }
    return out;
  }
  const std::string what =
      str_cat(spec.generator, " ", spec.width, "x", spec.height, " at density ", spec.density);
  if (blocked_maps == spec.max_attempts) {
    throw std::runtime_error(str_cat("fixed endpoints: the generator blocked start or goal on all ",
                                     spec.max_attempts, " maps (", what, ")"));
  }
  if (endpoints_failed) {
    throw std::runtime_error(
        str_cat("random endpoints: no two free cells min_distance = ", spec.min_distance,
                " apart found on ", spec.max_attempts, " maps (", what, ")"));
  }
  throw std::runtime_error(str_cat("require_solvable: start and goal not connected under ",
                                   to_string(spec.solvable_rule), " in ", spec.max_attempts,
                                   " maps (", what, ")"));
}

}  // namespace agv
