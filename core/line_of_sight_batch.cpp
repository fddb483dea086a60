#include "core/line_of_sight_batch.h"

// The public checks: each counts its collision checks and runs the active level's kernel
// (core/line_of_sight_kernel.h, core/simd_path.h).

#include "core/line_of_sight_kernel.h"

namespace agv {

// One table per compiled level (core/line_of_sight_kernel.cpp, core/CMakeLists.txt).
namespace sight_levels {
namespace baseline {
extern const SightKernel kKernel;
}
#if AGV_SIMD_LEVELS_X86
namespace avx2 {
extern const SightKernel kKernel;
}
namespace avx512 {
extern const SightKernel kKernel;
}
#endif
}  // namespace sight_levels

const SightKernel* sight_kernel(SimdPath path) {
#if AGV_SIMD_LEVELS_X86
  return level_kernel(path, &sight_levels::baseline::kKernel, &sight_levels::avx2::kKernel,
                      &sight_levels::avx512::kKernel);
#else
  return level_kernel<SightKernel>(path, &sight_levels::baseline::kKernel, nullptr, nullptr);
#endif
}

const SightKernel& active_sight_kernel() {
  static const SightKernel& kernel = *sight_kernel(active_simd_path());
  return kernel;
}

bool segment_free(const Grid& grid, Point a, Point b, const SightRule& rule) {
  count_collision_checks(1);
  return active_sight_kernel().segment(grid, a, b, rule);
}

void segments_free(const Grid& grid, std::span<const Point> a, std::span<const Point> b,
                   const SightRule& rule, std::span<std::uint8_t> out) {
  count_collision_checks(static_cast<std::int64_t>(out.size()));
  active_sight_kernel().segments(grid, a, b, rule, out);
}

void segments_free_from(const Grid& grid, Point from, std::span<const Point> to,
                        const SightRule& rule, std::span<std::uint8_t> out) {
  count_collision_checks(static_cast<std::int64_t>(out.size()));
  active_sight_kernel().segments_from(grid, from, to, rule, out);
}

void points_free(const Grid& grid, std::span<const Point> points, const SightRule& rule,
                 std::span<std::uint8_t> out) {
  count_collision_checks(static_cast<std::int64_t>(out.size()));
  active_sight_kernel().points(grid, points, rule, out);
}

}  // namespace agv
