#include "engine/plan/sweep_results.h"

#include <limits>
#include <memory>
#include <stdexcept>

namespace agv {

void SweepResults::store(std::int64_t task, std::size_t planner, RunSlot slot,
                         const MapSlot& map_slot) {
  slot.done = true;
  run(task, planner) = std::move(slot);
  MapSlot& ms = map(task);
  if (!ms.done && map_slot.done) ms = map_slot;
}

void SweepResults::allocate(const SweepCell& cell) {
  CellResults& c = cells_of(cell);
  if (c.digest) throw std::logic_error("cell " + cell.key + " was released: read its digest");
  if (!c.runs.empty()) return;
  c.runs.resize(static_cast<std::size_t>(cell.maps) * labels.size());
  for (auto& r : c.runs) r.metrics.fill(std::numeric_limits<double>::quiet_NaN());
}

void SweepResults::release(const SweepCell& cell, CellDigest digest) {
  CellResults& c = cells_of(cell);
  c.digest = std::make_shared<const CellDigest>(std::move(digest));
  std::vector<RunSlot>().swap(c.runs);
}

const RunSlot& SweepResults::unallocated_slot(const SweepCell& cell) const {
  if (cells_of(cell).digest)
    throw std::logic_error("cell " + cell.key + " was released: read its digest");
  static const RunSlot none = [] {
    RunSlot s;
    s.metrics.fill(std::numeric_limits<double>::quiet_NaN());
    return s;
  }();
  return none;
}

std::vector<std::size_t> SweepResults::pending_planners(std::int64_t task) const {
  if (released(plan.cell_of(task))) return {};
  std::vector<std::size_t> pending;
  for (std::size_t p = 0; p < labels.size(); ++p)
    if (scheduled(task, p) && !run(task, p).done) pending.push_back(p);
  return pending;
}

SweepResults empty_results(const SweepConfig& config) {
  SweepResults res;
  res.plan = plan_sweep(config);
  res.config_hash = agv::config_hash(config);
  for (const auto& p : config.planners) res.labels.push_back(p.label);
  res.cells.resize(res.plan.cells.size());
  for (const auto& cell : res.plan.cells) {
    CellResults& c = res.cells[static_cast<std::size_t>(cell.index)];
    c.maps.resize(static_cast<std::size_t>(cell.maps));
    for (const auto& p : config.planners) c.scoped_maps.push_back(scoped_maps(p, cell));
  }
  return res;
}

Coverage cell_coverage_of(const SweepResults& r, const SweepCell& cell) {
  Coverage c;
  const CellResults& slots = r.cells[static_cast<std::size_t>(cell.index)];
  for (const int maps : slots.scoped_maps) c.runs_expected += maps;
  if (slots.digest) {
    c.runs_present = slots.digest->runs_present;
    c.maps_missing = slots.digest->maps_missing;
    return c;
  }
  for (int m = 0; m < cell.maps; ++m) {
    bool any = false;
    for (std::size_t p = 0; p < r.labels.size(); ++p) any = any || r.run(cell, m, p).done;
    c.maps_missing += any ? 0 : 1;
  }
  for (const auto& s : slots.runs) c.runs_present += s.done ? 1 : 0;  // none when unallocated
  return c;
}

Coverage coverage_of(const SweepResults& r) {
  Coverage c;
  for (const auto& cell : r.plan.cells) {
    const Coverage cell_c = cell_coverage_of(r, cell);
    c.runs_expected += cell_c.runs_expected;
    c.runs_present += cell_c.runs_present;
    c.maps_missing += cell_c.maps_missing;
  }
  return c;
}

void update_completeness(SweepResults& results) {
  // Only scheduled runs can be done: the runner skips the others and the journal refuses them.
  const Coverage c = coverage_of(results);
  results.complete = c.runs_present == c.runs_expected;
}

}  // namespace agv
