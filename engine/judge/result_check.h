#pragma once
// What a planner hands back beyond its path, checked before the engine measures anything: its
// outcome and collision rule are values of their enums (a plugin can return any integer there,
// and the engine indexes by them), and the names of its extra metrics and phases. An extra
// metric may not take a name the engine measures itself (a run metric, a work counter, a
// trajectory verdict's metric): it would replace the measured value in the journal and the
// report. No name may be empty or given twice. Its phase times are on the thread CPU clock the
// engine times the whole call with (algos/planner.h PhaseTimer): none is negative or longer
// than the call (a planner filling them in itself could otherwise put any number into the
// report's timing and its paired statistics).

#include <cstdint>
#include <string>

#include "algos/planner.h"

namespace agv {

// Empty when the result keeps to this; else why not, naming the field, metric or phase.
std::string result_contract_problem(const PlanResult& result);
// Empty when every phase time lies in [0, plan_time_ns] (the call's CPU time); else why not,
// naming the phase.
std::string phase_time_problem(const PlanResult& result, std::int64_t plan_time_ns);

}  // namespace agv
