#pragma once
// A sweep's runs as columns, one entry per run, for a front-end that hands them on as arrays
// (the Python module's DataFrame, docs/PYTHON.md): read from the run slots in memory, never from
// formatted records. A sink: each cell is read when it finishes (cell_done, before a released
// cell's slots are freed) and, at the end, every cell a resume restored whole; rows come in
// (cell, map index, planner) order whichever order the cells finished in, so the table of a
// config and seed is the same on any thread count.

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "engine/outputs/sweep_sink.h"

namespace agv {

struct RunColumns {
  std::vector<std::int32_t> cell;       // the plan's cell index
  std::vector<std::int32_t> map_index;  // within the cell
  std::vector<std::int32_t> planner;    // config index
  std::vector<std::uint8_t> outcome;    // Outcome's value
  std::vector<std::int64_t> plan_time_ns;
  // By metric_names: the journal's metric order (engine/outputs/run_record.h), then any other
  // extra a planner reported (a plugin's), by name; NaN where a run does not define it.
  std::vector<std::string> metric_names;
  std::vector<std::vector<double>> metrics;
  std::size_t rows() const { return cell.size(); }
};

// Rows appended one run at a time; extras outside the journal's metric order (a plugin's) get a
// column of their own, NaN in the rows before.
class RunRows {
 public:
  RunRows();
  void add(int cell, int map_index, int planner, const RunSlot& slot);
  std::size_t rows() const { return columns_.rows(); }
  // The rows in the order added; other extras' columns after the journal's, by name.
  RunColumns take();

 private:
  RunColumns columns_;
  std::map<std::string, std::vector<double>> other_;
};

// The blocks' rows one after the other: the journal's metric columns, then every other extra
// any block has, by name (NaN in the blocks without it).
RunColumns concatenate_runs(std::vector<RunColumns> blocks);

class RunTable : public SweepSink {
 public:
  void cell_done(const SweepCell& cell, const SweepResults& results) override;
  void finish(const SweepResults& results) override;
  // The runs read so far, in (cell, map index, planner) order; leaves the table empty.
  RunColumns take();

 private:
  void read_cell(const SweepCell& cell, const SweepResults& results);
  std::map<int, RunColumns> blocks_;  // by cell index
};

}  // namespace agv
