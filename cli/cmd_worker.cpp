// `agvbench worker`: internal, one --isolate worker process (engine/sweep/isolated_worker.h).
#include <memory>

#include "cli/command.h"
#include "cli/option_checks.h"
#include "engine/sweep/isolated_worker.h"

namespace agv {

Command add_worker_command(CLI::App& app) {
  auto memory_mb = std::make_shared<long long>(0);
  auto* sub = app.add_subcommand("worker", "");
  sub->add_option("--memory-mb", *memory_mb)->transform(integer_in({0, kIsolateMemoryRange.hi}));
  sub->group("");  // not in the help: the sweep starts it
  return {sub, [memory_mb] { return worker_main(*memory_mb); }, false};
}

}  // namespace agv
