#include "generators/uniform.h"

// Floyd's sampling: T draws, and the canvas itself is the membership set, so no index array.

namespace agv {

const ParamDecls<UniformOptions>& uniform_params() {
  static const ParamDecls<UniformOptions> decls;
  return decls;
}

void generate_uniform(const UniformOptions&, MapContext& ctx) {
  Canvas& c = ctx.canvas;
  c.reset(ctx.width, ctx.height, false);
  const std::int64_t m =
      static_cast<std::int64_t>(c.width()) * c.height() - std::ssize(ctx.reserved);
  // The k-th candidate, skipping reserved cells (reserved are in ascending padded order, which
  // is also ascending row-major order).
  std::vector<std::int64_t> reserved_rank;
  for (int r : ctx.reserved) {
    reserved_rank.push_back(static_cast<std::int64_t>(r / c.stride() - 1) * c.width() +
                            (r % c.stride() - 1));
  }
  auto candidate = [&](std::int64_t k) {
    for (std::int64_t r : reserved_rank) k += (k >= r) ? 1 : 0;
    return c.index(static_cast<int>(k % c.width()), static_cast<int>(k / c.width()));
  };
  // Floyd's algorithm: for j = M-T .. M-1 draw t in [0, j]; take t unless already taken, then j.
  for (std::int64_t j = m - ctx.target; j < m; ++j) {
    int i = candidate(ctx.rng.below(static_cast<std::uint32_t>(j + 1)));
    if (c.blocked_at(i)) i = candidate(j);
    c.set_at(i, true);
  }
}

}  // namespace agv
