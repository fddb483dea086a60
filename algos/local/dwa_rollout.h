#pragma once
// Step 3 of a DWA control step (algos/local/dwa.h): every sampled pair rolled out at once, the
// hot loop of DWA and the fusion planners. Compiled once per instruction-set level
// (algos/local/dwa_rollout_kernel.cpp, core/simd_path.h): its loops are what the compiler
// vectorises, 2 doubles a vector at x86-64's SSE2, 4 with AVX2. Every level gives the same values
// bit for bit (no FMA contraction; tests/algos/test_dwa.cpp compares them).

#include "core/simd_path.h"

namespace agv {

// Declared in algos/local/dwa.h, algos/local/unicycle.h, algos/planner.h and core/grid.h; only
// named here, so that dwa.cpp, which runs the kernel, and the kernel, which needs them whole,
// include this without a cycle.
class DeadlinePoller;
class Grid;
struct DwaParams;
struct DwaScratch;
struct DwaTarget;
struct DwaView;
struct Pose;

// The sample grid and rollout length of one control step.
struct StepShape {
  int nv = 1, nw = 1, n = 1;
  int steps = 1;  // K = round(predict_time / dt)
};

struct DwaRolloutKernel {
  // Per rollout (scratch sized for shape.n, v and w sampled): the first hit step (static,
  // other), the minimum clearances and how many local goals it has passed. False when `poll`
  // expired first.
  bool (*roll_out)(const DwaParams& p, const Pose& pose, const StepShape& shape,
                   const DwaTarget& target, const DwaView& view, DwaScratch& s,
                   DeadlinePoller* poll);
  // The squared static clearance at (x, y), capped at 1 (capped_static_clearance, squared).
  double (*capped_static_sq)(const Grid& grid, double x, double y);
};

// The kernel compiled for `path`, or nullptr when this build or CPU has no such level.
const DwaRolloutKernel* dwa_rollout_kernel(SimdPath path);

// The kernel of active_simd_path(), chosen once.
const DwaRolloutKernel& active_dwa_rollout_kernel();

}  // namespace agv
