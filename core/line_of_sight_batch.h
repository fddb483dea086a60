#pragma once
// Batched and vectorised line of sight over the grid's bit-packed rows (docs/PLANNERS.md "Line of
// sight and clearance": the hot loop of PSO and of every shortcut pass). Same verdicts, bit for
// bit, as the reference walk (segment_free_reference / check_segment in core/line_of_sight.h)
// for every SightRule: tests/core/test_los_simd.cpp checks 100 000 random segments per mode.
//
// Three paths, chosen by measurement (perf/bench_los.cpp, perf/README.md "Line of sight"):
// - Batches of short segments (under 16 cells along the major axis): 8 segments side by side
//   in SIMD lanes (core/line_of_sight_lanes.cpp), each lane stepping the reference walk one
//   column per step with the same IEEE operations; cell bits by gathers; no per-segment or
//   per-cell branch. 1.3-1.9x the reference on short segments.
// - A single long segment (24 cells and more): the first columns one at a time (most blocked
//   segments stop there), then blocks whose line crossings are evaluated in a vectorised loop and
//   whose covered cells are ORed without a branch per cell. Up to 1.6x the reference.
// - A single short segment: the reference walk itself, which nothing here beats.
// The clearance test (obstacle circles) of the vectorised paths takes each grid row's candidate
// cells as one masked word and computes the reference's exact squared distance only for the
// blocked bits among them.
//
// The shared segment_free() of core/line_of_sight.h is the single-segment dispatch, so
// shortcutting, key-point search, curve checks and the sampling planners all use it.

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
