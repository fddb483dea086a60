#pragma once
// Word-parallel line of sight over the grid's bit-packed rows (docs/PLANNERS.md "Line of sight
// and clearance": the hot loop of PSO and of every shortcut pass). Same verdicts, bit for bit, as
// the reference walk (segment_free_reference / check_segment in core/line_of_sight.h) for every
// SightRule: tests/core/test_los_simd.cpp compares them on random segments of every mode.
//
// One path for single segments and batches alike (core/line_of_sight_batch.cpp), chosen by
// measurement on AVX2 and AVX-512 CPUs (perf/bench_los.cpp, perf/README.md "Line of sight"):
// - an endpoint well inside a blocked cell ends the check (most segments on a dense map);
// - the walk's columns go in growing blocks, each screened first by one masked word test per
//   grid row over a box that holds every cell the walk could touch there (64 cells a test); only
//   a block whose box holds an obstacle is walked exactly, column by column, as the reference
//   walks it. No hand-written vector code (8-wide GCC vector lanes with gathers ran 0.1-0.25x
//   the reference on AVX2 and lost at some cases on AVX-512); the kernel is compiled once per
//   instruction-set level (core/line_of_sight_kernel.cpp, core/simd_path.h) and the process
//   runs the best its CPU has, so a portable build runs as fast as a native one.
// The clearance test (obstacle circles) takes each grid row's candidate cells as one masked
// word and computes the reference's exact squared distance only for the blocked bits among them.
//
// The shared segment_free() of core/line_of_sight.h is the same check, so shortcutting,
// key-point search, curve checks and the sampling planners all use it.

#include <cstdint>
#include <span>

#include "core/grid.h"
#include "core/line_of_sight.h"

namespace agv {

// out[i] = segment_free(grid, a[i], b[i], rule) (1 or 0). a, b and out have the same size.
void segments_free(const Grid& grid, std::span<const Point> a, std::span<const Point> b,
                   const SightRule& rule, std::span<std::uint8_t> out);

// Segments from one common point: out[i] = segment_free(grid, from, to[i], rule). The PSO's
// (swarm x 2) checks per iteration are two of these calls (algos/swarm/hma_star.cpp).
void segments_free_from(const Grid& grid, Point from, std::span<const Point> to,
                        const SightRule& rule, std::span<std::uint8_t> out);

// Sample points (curve checks): out[i] = segment_free(grid, p[i], p[i], rule), i.e. the point
// touches no blocked cell (a point on a cell edge or vertex touches every cell around it) and,
// under clearance, keeps every obstacle centre at >= radius.
void points_free(const Grid& grid, std::span<const Point> points, const SightRule& rule,
                 std::span<std::uint8_t> out);

}  // namespace agv
