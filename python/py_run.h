#pragma once
// agvbench._core.run: a whole sweep, as `agvbench run` makes it, on the engine's threads while
// the calling Python thread reports progress and watches for Ctrl-C; the report as a dict and
// the runs as numpy columns (engine/outputs/run_table.h) that the package makes a DataFrame of.

#include <pybind11/pybind11.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace agv::py_bind {

struct RunCall {
  nlohmann::json config;    // a config object; null when config_path names a file
  std::string config_path;  // a config file; empty for an object
  nlohmann::json threads;   // null: the config's
  std::string out;          // the report file; empty: none is written
  std::string runs_out;     // the journal; empty: the config's "runs", if any
  nlohmann::json shard;     // null, or [i, n]
  bool keep_runs = true;
};

// A dict: report, and (keep_runs) runs: the columns, cells, planners and outcome names.
// InputError naming the argument or config field; KeyboardInterrupt (or what `progress` raised)
// once the runs in flight are over and the journal is flushed.
pybind11::dict run(const RunCall& call, const pybind11::object& progress);

// One report from the journals of a sharded or interrupted sweep of call's config, as
// `agvbench merge`: a dict as run()'s (call.out: also written there; runs_out and shard unused).
pybind11::dict merge(const RunCall& call, const std::vector<std::string>& journals);

// A journal's runs (engine/outputs/journal_table.h) in the shape of run()'s "runs": cells of a
// generator with their generator, size and density (read off the cell key), a map file's cell
// with its key alone; seed None (a journal's records do not repeat it).
pybind11::dict read_journal(const std::string& path);

// The outcome names, indexed by the outcome codes of the columns.
pybind11::list outcome_names();

}  // namespace agv::py_bind
