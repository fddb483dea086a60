#pragma once
// CLI11 validators for the numeric options: every one goes through cli/cli_numbers.h (the whole
// argument one number in the range, the config's where it has the same setting), canonicalised
// before CLI11 converts it (transform, not check: CLI11 hands a check a copy of the text).

#include <CLI/CLI.hpp>

#include "engine/plan/sweep_config.h"

namespace agv {

CLI::Validator integer_in(IntRange range);
CLI::Validator number_in(NumberRange range);

// --isolate-memory (and the worker's --memory-mb): MiB of address space per worker.
inline constexpr IntRange kIsolateMemoryRange{64, 1LL << 40};

}  // namespace agv
