#pragma once
// Numbers on the command line, read strictly: the whole argument must be one base-10 number
// (no trailing text, no sign where the range has none, no overflow, no nan or inf), inside the
// range the config gives the same setting (engine/plan/sweep_config.h kSeedRange and the others),
// so `agvbench plan --seed -1` is refused exactly as `"seed": -1` is. Every numeric option of main
// and every number inside an option's text (--shard i/N, --start x,y, --size WxH) goes through
// these; failures are InputError naming the option.

#include <string>

#include "engine/plan/sweep_config.h"

namespace agv {

long long parse_cli_integer(const std::string& text, const std::string& option, IntRange range);
double parse_cli_number(const std::string& text, const std::string& option, NumberRange range);

// The same checks returning what is wrong instead of throwing ("" = fine; CLI11 validators put
// the option's name in front), and on success `text` rewritten in the canonical form ("010" ->
// "10"), so CLI11's own conversion, which reads a leading 0 as octal, reads the value checked.
std::string cli_integer_error(std::string& text, IntRange range);
std::string cli_number_error(std::string& text, NumberRange range);

// Any finite number: its range is checked where the value is used (--clearance: the collision
// model's own check, core/collision_model.h).
inline constexpr NumberRange kFiniteRange{-1e300, 1e300};

}  // namespace agv
