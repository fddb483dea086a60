#include "engine/outputs/run_table.h"

#include <set>

#include "engine/judge/run_metrics.h"
#include "engine/judge/statistics.h"
#include "engine/outputs/run_record.h"

namespace agv {

namespace {

// The column of `name` in the journal's metric order, or -1.
int metric_column(const std::string& name) {
  static const std::map<std::string, int> columns = [] {
    std::map<std::string, int> out;
    const auto& names = journal_metric_names();
    for (std::size_t i = 0; i < names.size(); ++i) out[names[i]] = static_cast<int>(i);
    return out;
  }();
  const auto it = columns.find(name);
  return it == columns.end() ? -1 : it->second;
}

}  // namespace

RunRows::RunRows() {
  columns_.metric_names = journal_metric_names();
  columns_.metrics.assign(columns_.metric_names.size(), {});
}

void RunRows::add(int cell, int map_index, int planner, const RunSlot& slot) {
  RunColumns& c = columns_;
  const std::size_t row = c.cell.size();
  c.cell.push_back(cell);
  c.map_index.push_back(map_index);
  c.planner.push_back(planner);
  c.outcome.push_back(static_cast<std::uint8_t>(slot.outcome));
  c.plan_time_ns.push_back(slot.plan_time_ns);
  for (std::size_t k = 0; k < c.metrics.size(); ++k)
    c.metrics[k].push_back(k < kRunMetricNames.size() ? slot.metrics[k] : kNaN);
  for (const auto& [name, value] : slot.extra) {
    const int k = metric_column(name);
    std::vector<double>& column = k >= 0 ? c.metrics[static_cast<std::size_t>(k)] : other_[name];
    column.resize(row + 1, kNaN);
    column[row] = value;
  }
}

RunColumns RunRows::take() {
  RunColumns out = std::move(columns_);
  for (auto& [name, column] : other_) {
    column.resize(out.rows(), kNaN);
    out.metric_names.push_back(name);
    out.metrics.push_back(std::move(column));
  }
  *this = RunRows();
  return out;
}

RunColumns concatenate_runs(std::vector<RunColumns> blocks) {
  // One block with the journal's columns alone (a one-cell sweep, a journal): it is the table.
  if (blocks.size() == 1 && blocks[0].metric_names == journal_metric_names())
    return std::move(blocks[0]);
  RunColumns out;
  out.metric_names = journal_metric_names();
  std::set<std::string> others;
  for (const RunColumns& b : blocks)
    for (std::size_t k = out.metric_names.size(); k < b.metric_names.size(); ++k)
      others.insert(b.metric_names[k]);
  out.metric_names.insert(out.metric_names.end(), others.begin(), others.end());
  std::map<std::string, std::size_t> column_of;
  for (std::size_t k = 0; k < out.metric_names.size(); ++k) column_of[out.metric_names[k]] = k;
  out.metrics.assign(out.metric_names.size(), {});
  const auto append = [](auto& to, const auto& from) {
    to.insert(to.end(), from.begin(), from.end());
  };
  for (const RunColumns& b : blocks) {
    append(out.cell, b.cell);
    append(out.map_index, b.map_index);
    append(out.planner, b.planner);
    append(out.outcome, b.outcome);
    append(out.plan_time_ns, b.plan_time_ns);
    for (std::size_t k = 0; k < b.metric_names.size(); ++k)
      append(out.metrics[column_of[b.metric_names[k]]], b.metrics[k]);
    for (auto& column : out.metrics) column.resize(out.rows(), kNaN);  // extras it lacks
  }
  return out;
}

void RunTable::read_cell(const SweepCell& cell, const SweepResults& results) {
  if (blocks_.count(cell.index) != 0 || results.released(cell)) return;
  RunRows rows;
  const std::size_t planners = results.labels.size();
  for (int m = 0; m < cell.maps; ++m) {
    for (std::size_t p = 0; p < planners; ++p) {
      const RunSlot& slot = results.run(cell, m, p);
      if (slot.done) rows.add(cell.index, m, static_cast<int>(p), slot);
    }
  }
  blocks_[cell.index] = rows.take();
}

void RunTable::cell_done(const SweepCell& cell, const SweepResults& results) {
  read_cell(cell, results);
}

void RunTable::finish(const SweepResults& results) {
  for (const SweepCell& cell : results.plan.cells) read_cell(cell, results);
}

RunColumns RunTable::take() {
  std::vector<RunColumns> blocks;
  for (auto& [index, b] : blocks_) blocks.push_back(std::move(b));
  blocks_.clear();
  return concatenate_runs(std::move(blocks));
}

}  // namespace agv
