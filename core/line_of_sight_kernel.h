#pragma once
// The line-of-sight kernel's entry points as one table, one table per instruction-set level this
// build compiled (core/line_of_sight_kernel.cpp, core/simd_path.h). core/line_of_sight_batch.cpp
// counts the checks and calls the active level's table; tests and perf/bench_los call each level's
// table directly, to compare and time every level on one machine. No entry point counts
// collision checks.

#include <cstdint>
#include <span>

#include "core/grid.h"
#include "core/line_of_sight.h"
#include "core/simd_path.h"

namespace agv {

struct SightKernel {
  bool (*segment)(const Grid&, Point, Point, const SightRule&);
  void (*segments)(const Grid&, std::span<const Point>, std::span<const Point>, const SightRule&,
                   std::span<std::uint8_t>);
  void (*segments_from)(const Grid&, Point, std::span<const Point>, const SightRule&,
                        std::span<std::uint8_t>);
  void (*points)(const Grid&, std::span<const Point>, const SightRule&, std::span<std::uint8_t>);
};

// The kernel compiled for `path`, or nullptr when this build has no such copy (only x86-64 builds
// have avx2 and avx512) or the CPU cannot run it.
const SightKernel* sight_kernel(SimdPath path);

// The kernel of active_simd_path(), chosen once.
const SightKernel& active_sight_kernel();

}  // namespace agv
