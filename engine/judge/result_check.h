#pragma once
// What a planner hands back beyond its path, checked before the engine measures anything: its
// outcome and collision rule are values of their enums (a plugin can return any integer there,
// and the engine indexes by them), and the names of its extra metrics and phases. An extra
// metric may not take a name the engine measures itself (a run metric, a work counter, a
// trajectory verdict's metric): it would replace the measured value in the journal and the
// report. No name may be empty or given twice.

#include <string>

#include "algos/planner.h"

namespace agv {

// Empty when the result keeps to this; else why not, naming the field, metric or phase.
std::string result_contract_problem(const PlanResult& result);

}  // namespace agv
