#include "engine/run_record.h"

#include <cmath>

namespace agv {

using nlohmann::json;

RunSlot run_slot_of(const RunOutput& run) {
  RunSlot slot;
  slot.outcome = run.outcome;
  slot.metrics = run.metrics;
  slot.plan_time_ns = run.plan_time_ns;
  slot.phases = run.result.phases;
  slot.extra = run.result.extra;
  return slot;
}

json run_record(const std::string& config_hash, std::uint64_t seed, const SweepCell& cell,
                int map_index, const PlannerEntry& planner, const MapSlot& map,
                const RunOutput& run) {
  json metrics = json::object();
  for (std::size_t i = 0; i < kRunMetricNames.size(); ++i) {
    const double v = run.metrics[i];
    metrics[std::string(kRunMetricNames[i])] = std::isfinite(v) ? json(v) : json(nullptr);
  }
  for (const auto& [name, value] : run.result.extra)
    metrics[name] = std::isfinite(value) ? json(value) : json(nullptr);
  json phases = json::object();
  for (const auto& p : run.result.phases) phases[p.name] = p.ns;
  json rec = {
      {"tool", kJournalTool},
      {"journal_version", kJournalVersion},
      {"task_id", task_id(config_hash, cell, map_index, planner.label)},
      {"config_hash", config_hash},
      {"planner", planner.label},
      {"planner_name", planner.name},
      {"generator", cell.generator},
      {"size", {cell.size.width, cell.size.height}},
      {"density", cell.density},
      {"cell", cell.key},
      {"map_index", map_index},
      {"seed", seed},
      {"map", {{"rejections", map.rejections}, {"obstacle_fraction", map.obstacle_fraction}}},
      {"outcome", std::string(to_string(run.outcome))},
      {"metrics", metrics},
      {"timing", {{"plan_time_ns", run.plan_time_ns}, {"phases", phases}}}};
  // A map source's cell: the file its maps come from, so a resume can say which file changed.
  if (cell.file != nullptr)
    rec["map_file"] = {{"name", cell.file->name}, {"content_hash", cell.file->content_hash}};
  if (!run.message.empty()) rec["message"] = run.message;
  return rec;
}

}  // namespace agv
