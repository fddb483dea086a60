#include "engine/plan/sweep_config.h"

#include <stdexcept>

#include "core/json_text.h"
#include "core/rng.h"

namespace agv {

using nlohmann::json;

json map_files_json(const MapFileSet& set) {
  json out = json::array();
  for (const auto& f : set.files)
    out.push_back({{"name", f.name}, {"content_hash", f.content_hash}});
  return out;
}

json looser_json(const std::vector<ModelDeviation>& deviations) {
  json looser = json::object();
  for (const auto& d : deviations) looser[d.param] = d.value;
  return looser;
}

namespace {

const char* endpoints_name(EndpointMode mode) {
  return mode == EndpointMode::corners  ? "corners"
         : mode == EndpointMode::random ? "random"
                                        : "fixed";
}

json sizes_json(const std::vector<GridSize>& sizes) {
  json out = json::array();
  for (const auto& s : sizes) out.push_back({s.width, s.height});
  return out;
}

// The config as run, but for the fields only some configs have (below).
json config_fields(const SweepConfig& c) {
  json planners = json::array();
  for (const auto& p : c.planners) {
    json entry = {{"label", p.label}, {"name", p.name}, {"params", p.resolved}};
    if (!p.looser_than_model.empty()) entry["looser_than_model"] = looser_json(p.looser_than_model);
    // Written only when scoped, so configs without scopes keep their hash (and journals).
    if (!p.only.everywhere()) {
      // Only the axes it restricts: parse_config reads this back (isolation workers get it).
      json only = json::object();
      if (!p.only.generators.empty()) only["generators"] = p.only.generators;
      if (!p.only.sizes.empty()) only["sizes"] = sizes_json(p.only.sizes);
      if (!p.only.densities.empty()) only["densities"] = p.only.densities;
      if (p.only.maps_per_cell > 0) only["maps_per_cell"] = p.only.maps_per_cell;
      entry["only"] = std::move(only);
    }
    planners.push_back(std::move(entry));
  }
  json generators = json::array();
  for (const auto& g : c.generators) {
    generators.push_back({{"name", g.name}, {"params", g.resolved}});
    if (g.files) generators.back()["map_files"] = map_files_json(*g.files);
  }
  const MapSpec& m = c.map;
  return {{"name", c.name},
          {"seed", c.seed},
          {"generators", generators},
          {"sizes", sizes_json(c.sizes)},
          {"densities", c.densities},
          {"maps_per_cell", c.maps_per_cell},
          {"collision",
           {{"corner_rule", std::string(to_string(c.collision.corner_rule))},
            {"clearance", c.collision.clearance}}},
          {"map",
           {{"endpoints", endpoints_name(m.endpoints)},
            {"min_distance", m.min_distance},
            {"require_solvable", m.require_solvable},
            {"solvable_rule", std::string(to_string(m.solvable_rule))},
            {"max_attempts", m.max_attempts},
            {"cell_edge", m.cell_edge}}},
          {"planners", planners},
          {"baseline", c.baseline},
          {"time_limit_s", c.time_limit_s},
          {"motion",
           {{"line_speed_mps", c.motion.line_speed_mps},
            {"node_time_s", c.motion.node_time_s},
            {"turn_speed_radps", c.motion.turn_speed_radps}}}};
}

}  // namespace

// The fields above, plus what only some configs have, written only when present so that the
// other configs keep their hash (and journals): fixed endpoints' cells, a reference left out,
// the "sources" commentary and the plugins that ran.
json config_as_run(const SweepConfig& c) {
  json out = config_fields(c);
  if (!c.any_angle_reference) out["references"] = {{"any_angle", false}};
  if (c.map.endpoints == EndpointMode::fixed) {
    out["map"]["start"] = {c.map.start.x, c.map.start.y};
    out["map"]["goal"] = {c.map.goal.x, c.map.goal.y};
  }
  if (!c.sources.empty()) out["sources"] = c.sources;
  if (!c.plugins.empty()) {
    json plugins = json::array();
    for (const auto& p : c.plugins) plugins.push_back(p.as_run());
    out["plugins"] = std::move(plugins);
  }
  return out;
}

std::optional<std::size_t> planner_index(const SweepConfig& c, const std::string& label) {
  for (std::size_t p = 0; p < c.planners.size(); ++p)
    if (c.planners[p].label == label) return p;
  return std::nullopt;
}

std::size_t baseline_index(const SweepConfig& c) {
  const auto base = planner_index(c, c.baseline);
  if (!base) throw std::logic_error("baseline \"" + c.baseline + "\" is no planner of the config");
  return *base;
}

std::string config_hash(const SweepConfig& c) { return config_hash_of(config_as_run(c)); }

std::string config_hash_of(json as_run) {
  as_run.erase("sources");  // commentary: a reworded source is the same sweep
  const std::uint64_t h = stable_hash(json_text(as_run));
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

}  // namespace agv
