#pragma once
// The size of a sweep in words, as `run` and `validate` print it.

#include <string>

#include "engine/plan/sweep_config.h"
#include "engine/plan/sweep_plan.h"

namespace agv {

// "16 cells x 100 maps x 13 planners = 20800 runs", or, with scoped planners, what they leave.
std::string run_count_text(const SweepConfig& config, const SweepPlan& plan);

}  // namespace agv
