#include "engine/plan/config_loader.h"

#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

#include "core/json_reader.h"
#include "core/json_text.h"
#include "core/rng.h"
#include "core/text_file.h"
#include "engine/plan/sweep_plan.h"
#include "engine/plan/sweep_size.h"

namespace agv {

using nlohmann::json;

namespace {

// An optional object ("map", "collision", "motion"): absent reads as {}, so leaving it out and
// writing it empty give the same defaults.
const json& optional_object(ObjectReader& r, const std::string& key) {
  static const json empty = json::object();
  return r.has(key) ? r.raw(key) : empty;
}

const json& require_array(ObjectReader& r, const std::string& key) {
  const json& v = r.raw(key);
  if (!v.is_array() || v.empty()) throw InputError(r.field(key) + ": expected a non-empty array");
  return v;
}

std::vector<GridSize> parse_sizes(ObjectReader& r) {
  std::vector<GridSize> sizes;
  std::map<GridSize, std::size_t> first_index;
  const json& arr = require_array(r, "sizes");
  for (std::size_t i = 0; i < arr.size(); ++i) {
    const std::string f = r.field("sizes") + "[" + std::to_string(i) + "]";
    const json& s = arr[i];
    if (s.is_number_integer()) {
      const auto n = static_cast<int>(ObjectReader::check_integer(s, f, kMapSideRange));
      sizes.push_back({n, n});
    } else if (s.is_array() && s.size() == 2) {
      sizes.push_back(
          {static_cast<int>(ObjectReader::check_integer(s[0], f + "[0]", kMapSideRange)),
           static_cast<int>(ObjectReader::check_integer(s[1], f + "[1]", kMapSideRange))});
    } else {
      throw InputError(f + ": expected a side length or [width, height]");
    }
    // Two equal sizes would be two cells with one key (a resume would then run both twice).
    const auto [it, added] = first_index.emplace(sizes.back(), i);
    if (!added)
      throw InputError(f + ": " + std::to_string(sizes.back().width) + "x" +
                       std::to_string(sizes.back().height) + " is also " + r.field("sizes") + "[" +
                       std::to_string(it->second) + "] (give each size once)");
  }
  return sizes;
}

// A shape parameter in "map" is from configs before the generators were registered: say where
// it goes now rather than calling it unknown.
void refuse_moved_shape_params(const json& j) {
  for (const auto& [key, value] : j.items()) {
    for (const auto& g : generator_registry()) {
      for (const auto& spec : g.params) {
        if (spec.name != key) continue;
        throw InputError(
            "map." + key + ": a shape parameter of generator \"" + g.name +
            "\"; it now goes in that generator's entry: \"generators\": [{\"name\": \"" + g.name +
            "\", \"params\": {\"" + key + "\": " + json_text(value) + "}}]");
      }
    }
  }
}

// A registered generator or map source: InputError naming `where` otherwise.
void check_generator_name(const std::string& name, const std::string& where) {
  if (find_map_source(name) != nullptr) return;
  generator_or_throw(name, where);
}

// Generator names (a planner's "only" scope).
std::vector<std::string> parse_generator_names(ObjectReader& r) {
  std::vector<std::string> generators;
  const json& arr = require_array(r, "generators");
  for (std::size_t i = 0; i < arr.size(); ++i) {
    const std::string f = r.field("generators") + "[" + std::to_string(i) + "]";
    if (!arr[i].is_string()) throw InputError(f + ": expected a generator name");
    const auto name = arr[i].get<std::string>();
    check_generator_name(name, f);
    generators.push_back(name);
  }
  return generators;
}

// The sweep's generators, each a name or {"name": ..., "params": {...}}; the shape parameters
// are resolved once sizes are known (a maze corridor must fit every size).
std::vector<GeneratorEntry> parse_generators(ObjectReader& r, std::vector<json>& stated_files) {
  std::vector<GeneratorEntry> generators;
  std::set<std::string> names;
  const json& arr = require_array(r, "generators");
  for (std::size_t i = 0; i < arr.size(); ++i) {
    const std::string f = r.field("generators") + "[" + std::to_string(i) + "]";
    GeneratorEntry e;
    if (arr[i].is_string()) {
      e.name = arr[i].get<std::string>();
    } else if (arr[i].is_object()) {
      ObjectReader g(arr[i], f + ".");
      if (!g.has("name")) throw InputError(f + ".name: missing");
      e.name = g.string("name", "");
      if (g.has("params")) e.params = g.raw("params");
      // Written by config_as_run for a map source: checked against the files once they are read.
      if (g.has("map_files")) {
        stated_files.resize(i + 1);
        stated_files[i] = g.raw("map_files");
      }
      g.finish();
    } else {
      throw InputError(f + ": expected a generator name or {\"name\": ..., \"params\": {...}}");
    }
    check_generator_name(e.name, f);
    if (!names.insert(e.name).second)
      throw InputError(f + ": generator \"" + e.name + "\" appears twice (it names the cells)");
    generators.push_back(std::move(e));
  }
  return generators;
}

void resolve_generators(std::vector<GeneratorEntry>& generators,
                        const std::vector<GridSize>& sizes) {
  for (std::size_t i = 0; i < generators.size(); ++i) {
    GeneratorEntry& e = generators[i];
    const std::string where = "generators[" + std::to_string(i) + "].params";
    if (find_map_source(e.name) != nullptr) continue;  // read with the map options
    const GeneratorInfo& info = *find_generator(e.name);
    for (const auto& size : sizes)
      e.resolved =
          resolve_generator_params(info, e.params, where, size.width, size.height).values();
  }
}

// Every cell's map spec through make_map's own checks (generators/map_generators.h), so what the
// first map of a cell would refuse (a min_distance beyond a small size's diagonal) is refused at
// load, naming the field and the size, before any file is opened. The checks depend on a cell's
// density only through its range, which every density of the sweep has passed, so one density
// stands for all.
void check_cells(const SweepConfig& c) {
  for (std::size_t g = 0; g < c.generators.size(); ++g) {
    if (c.generators[g].files) continue;  // read_map_files checked its files
    for (std::size_t k = 0; k < c.sizes.size(); ++k) {
      MapSpec spec = c.map;
      spec.generator = c.generators[g].name;
      spec.params = c.generators[g].resolved;
      spec.width = c.sizes[k].width;
      spec.height = c.sizes[k].height;
      spec.density = c.densities.front();
      try {
        check_map_spec(spec);
      } catch (const std::invalid_argument& e) {
        const std::string what = e.what();
        const std::string object =
            what.rfind("params.", 0) == 0 ? "generators[" + std::to_string(g) + "]." : "map.";
        throw InputError(object + what + ", for sizes[" + std::to_string(k) + "] (" +
                         std::to_string(spec.width) + "x" + std::to_string(spec.height) + ")");
      }
    }
  }
}

// Reads every map source's files (InputError naming the file and line), checks each file against
// the sweep's endpoint rule, and compares them with the files a config_as_run names (an isolation
// worker's, a report's), so a map file changed in between is refused by name.
void read_map_files(SweepConfig& c, const std::vector<json>& stated_files) {
  for (std::size_t i = 0; i < c.generators.size(); ++i) {
    GeneratorEntry& e = c.generators[i];
    const MapSourceInfo* source = find_map_source(e.name);
    if (source == nullptr) continue;
    const std::string where = "generators[" + std::to_string(i) + "].params";
    auto set =
        std::make_shared<MapFileSet>(source->load(e.params, c.base_dir, c.map.cell_edge, where));
    if (set->queries == QuerySource::endpoints)
      for (const auto& f : set->files) check_file_endpoints(f, c.map);
    if (i < stated_files.size() && !stated_files[i].is_null()) {
      const json now = map_files_json(*set);
      const json& then = stated_files[i];
      for (std::size_t k = 0; k < now.size(); ++k) {
        if (!then.is_array() || k >= then.size() || then[k].value("name", "") != now[k]["name"])
          throw InputError("generators[" + std::to_string(i) + "].map_files: " + json_text(then) +
                           " is not the files its params match now (" + json_text(now) + ")");
        if (then[k].value("content_hash", "") != now[k]["content_hash"])
          throw InputError("generators[" + std::to_string(i) + "]: map file " + set->files[k].path +
                           " changed (content hash " + then[k].value("content_hash", "") +
                           " then, " + now[k]["content_hash"].get<std::string>() + " now)");
      }
      if (then.size() != now.size())
        throw InputError("generators[" + std::to_string(i) + "].map_files: " + json_text(then) +
                         " is not the files its params match now (" + json_text(now) + ")");
    }
    e.resolved = set->resolved;
    e.files = std::move(set);
  }
}

std::vector<double> parse_densities(ObjectReader& r) {
  std::vector<double> densities;
  std::map<std::string, std::size_t> first_index;  // by density_text
  const json& arr = require_array(r, "densities");
  for (std::size_t i = 0; i < arr.size(); ++i) {
    const std::string f = r.field("densities") + "[" + std::to_string(i) + "]";
    densities.push_back(ObjectReader::check_number(arr[i], f, kDensityRange));
    // A density names its cells by density_text (engine/plan/sweep_plan.h): two that print alike
    // would be two cells with one key.
    const std::string text = density_text(densities.back());
    const auto [it, added] = first_index.emplace(text, i);
    if (!added)
      throw InputError(
          f + ": " + json_text(arr[i]) + " names the same cells as " + r.field("densities") + "[" +
          std::to_string(it->second) + "] (" + json_text(arr[it->second]) +
          "): densities are told apart by their first 10 significant digits (\"" + text + "\")");
  }
  return densities;
}

// Every value a scope names must be one the sweep has: a typo would otherwise leave a planner
// silently out of a cell.
template <class T>
void require_subset(const std::vector<T>& values, const std::vector<T>& sweep,
                    const std::string& field, const std::string& axis) {
  for (std::size_t i = 0; i < values.size(); ++i) {
    bool found = false;
    for (const auto& v : sweep) found = found || v == values[i];
    if (!found)
      throw InputError(field + "[" + std::to_string(i) + "]: not one of the sweep's " + axis);
  }
}

PlannerScope parse_scope(const json& j, const std::string& where, const SweepConfig& c) {
  ObjectReader r(j, where + ".only.");
  PlannerScope s;
  if (r.has("generators")) s.generators = parse_generator_names(r);
  if (r.has("sizes")) s.sizes = parse_sizes(r);
  if (r.has("densities")) s.densities = parse_densities(r);
  s.maps_per_cell = static_cast<int>(r.integer("maps_per_cell", 0, 1, c.maps_per_cell));
  r.finish();
  std::vector<std::string> sweep_generators;
  for (const auto& g : c.generators) sweep_generators.push_back(g.name);
  require_subset(s.generators, sweep_generators, r.field("generators"), "generators");
  require_subset(s.sizes, c.sizes, r.field("sizes"), "sizes");
  require_subset(s.densities, c.densities, r.field("densities"), "densities");
  return s;
}

std::vector<PlannerEntry> parse_planners(ObjectReader& r, const SweepConfig& sweep) {
  std::vector<PlannerEntry> planners;
  std::set<std::string> labels;
  const json& arr = require_array(r, "planners");
  for (std::size_t i = 0; i < arr.size(); ++i) {
    const std::string where = "planners[" + std::to_string(i) + "]";
    PlannerEntry e;
    json stated_looser;
    if (arr[i].is_string()) {
      e.name = arr[i].get<std::string>();
    } else if (arr[i].is_object()) {
      ObjectReader p(arr[i], where + ".");
      if (!p.has("name")) throw InputError(where + ".name: missing");
      e.name = p.string("name", "");
      e.label = p.string("label", "");
      if (p.has("params")) e.params = p.raw("params");
      if (p.has("only")) e.only = parse_scope(p.raw("only"), where, sweep);
      // Written by config_as_run (a report's config, an isolation worker's): derived, so it is
      // only checked against what the parameters give below.
      if (p.has("looser_than_model")) stated_looser = p.raw("looser_than_model");
      p.finish();
    } else {
      throw InputError(
          where +
          ": expected a planner name or {\"name\": ..., \"params\": {...}, \"only\": {...}}");
    }
    if (e.label.empty()) e.label = e.name;
    if (!labels.insert(e.label).second)
      throw InputError(where + ".label: \"" + e.label +
                       "\" appears twice (give one of them a distinct \"label\")");
    ConfiguredPlanner configured =
        configure_planner(e.name, e.params, where + " (" + e.label + ")", sweep.collision);
    e.resolved = configured.params.values();
    e.looser_than_model = std::move(configured.looser_than_model);
    if (!stated_looser.is_null() && stated_looser != looser_json(e.looser_than_model))
      throw InputError(where + ".looser_than_model: " + json_text(stated_looser) +
                       " is not what its params give (" +
                       json_text(looser_json(e.looser_than_model)) + ")");
    // A planner set looser than the model is a variant: its label must say it is not the
    // registry's planner, whose results are those under the model.
    if (!e.looser_than_model.empty() && e.label == e.name) {
      const ModelDeviation& d = e.looser_than_model.front();
      throw InputError(where + ".params." + d.param + ": " + json_text(d.value) +
                       " is looser than the sweep's collision model (" +
                       to_string(sweep.collision) + ", which asks for " + json_text(d.model) +
                       "); such a variant needs a \"label\" of its own, and its paths are "
                       "still judged under the model");
    }
    planners.push_back(std::move(e));
  }
  return planners;
}

// "sources": where each value of the config comes from (a paper, its section or table), as free
// text: an object whose values are strings or objects of the same kind. Commentary: echoed in
// the report's config, left out of the config hash.
json parse_sources(const json& j, const std::string& where) {
  if (!j.is_object())
    throw InputError(where + ": expected an object of {\"field\": \"where its value comes from\"}");
  for (const auto& [key, value] : j.items()) {
    if (value.is_object()) {
      parse_sources(value, where + "." + key);
    } else if (!value.is_string()) {
      throw InputError(where + "." + key + ": expected a string (free text) or an object, got " +
                       json_text(value));
    }
  }
  return j;
}

// "plugins": shared-library paths (relative ones from the config's folder) or, in a config as
// run, the records of engine/plan/plugins.h, which must still match the file. Loaded before the
// planners are read, so a plugin's planners can be named.
void load_config_plugins(const json& list, const std::string& base_dir) {
  if (!list.is_array()) throw InputError("plugins: expected a list of plugin paths");
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string where = "plugins[" + std::to_string(i) + "]";
    if (!list[i].is_string()) {
      load_recorded_plugin(list[i], where);
      continue;
    }
    std::filesystem::path path = list[i].get<std::string>();
    if (path.empty()) throw InputError(where + ": empty path");
    if (path.is_relative() && !base_dir.empty()) path = std::filesystem::path(base_dir) / path;
    load_plugin(path.string(), where);
  }
}

}  // namespace

CollisionModel parse_collision(const json& j) {
  ObjectReader r(j, "collision.");
  CollisionModel model;
  model.corner_rule =
      *corner_rule_from_string(r.choice("corner_rule", std::string(to_string(model.corner_rule)),
                                        {"allow", "no_squeeze", "no_corner_cut"}));
  model.clearance = r.number("clearance", 0.0, -1e300, 1e300);
  check_model_clearance(model, "collision.clearance");
  r.finish();
  return model;
}

void parse_map_options(const json& j, MapSpec& map) {
  ObjectReader r(j, "map.");
  if (j.is_object()) refuse_moved_shape_params(j);
  const std::string endpoints = r.choice("endpoints", "corners", {"corners", "random", "fixed"});
  map.endpoints = endpoints == "corners"  ? EndpointMode::corners
                  : endpoints == "random" ? EndpointMode::random
                                          : EndpointMode::fixed;
  map.min_distance = r.number("min_distance", 0.0, 0.0, 1e6);
  // Fixed endpoints: 0-based [x, y] cells (x right, y down, as `plan --start` and the records);
  // whether they fit each size is checked with the cells (check_cells).
  for (const auto& [key, cell] : {std::pair{"start", &map.start}, std::pair{"goal", &map.goal}}) {
    const bool given = r.has(key);
    if (given != (map.endpoints == EndpointMode::fixed))
      throw InputError(r.field(key) + (given ? ": only with \"endpoints\": \"fixed\""
                                             : ": missing (\"endpoints\": \"fixed\" needs "
                                               "\"start\" and \"goal\" as [x, y])"));
    if (!given) continue;
    const json& v = r.raw(key);
    if (!v.is_array() || v.size() != 2)
      throw InputError(r.field(key) + ": expected [x, y] (0-based cells), got " + json_text(v));
    cell->x = static_cast<int>(
        ObjectReader::check_integer(v[0], r.field(key) + "[0]", 0, kMapSideRange.hi - 1));
    cell->y = static_cast<int>(
        ObjectReader::check_integer(v[1], r.field(key) + "[1]", 0, kMapSideRange.hi - 1));
  }
  map.require_solvable = r.boolean("require_solvable", true);
  map.solvable_rule =
      *corner_rule_from_string(r.choice("solvable_rule", std::string(to_string(map.solvable_rule)),
                                        {"allow", "no_squeeze", "no_corner_cut"}));
  map.max_attempts = static_cast<int>(r.integer("max_attempts", 1000, 1, 1000000));
  map.cell_edge = r.number("cell_edge", 1.0, 1e-6, 1e6);
  r.finish();
}

SweepConfig parse_config(const json& j, const std::string& base_dir) {
  SweepConfig c;
  c.base_dir = base_dir;
  std::vector<json> stated_files;
  refuse_nul_strings(j, "");
  ObjectReader r(j, "");
  if (r.has("plugins")) load_config_plugins(r.raw("plugins"), base_dir);
  c.plugins = loaded_plugins();
  c.name = r.string("name", c.name);
  c.seed = static_cast<std::uint64_t>(r.integer("seed", 1, kSeedRange));
  if (r.has("generators")) c.generators = parse_generators(r, stated_files);
  if (r.has("sizes")) c.sizes = parse_sizes(r);
  if (r.has("densities")) c.densities = parse_densities(r);
  resolve_generators(c.generators, c.sizes);
  c.maps_per_cell =
      static_cast<int>(r.integer("maps_per_cell", c.maps_per_cell, kMapsPerCellRange));
  c.collision = parse_collision(optional_object(r, "collision"));
  c.map.solvable_rule = c.collision.corner_rule;
  parse_map_options(optional_object(r, "map"), c.map);
  read_map_files(c, stated_files);
  if (!r.has("planners")) throw InputError("planners: missing (list at least one planner)");
  c.planners = parse_planners(r, c);
  c.baseline = r.string("baseline", "");
  if (c.baseline.empty()) {
    c.baseline = planner_index(c, "astar") ? "astar" : c.planners.front().label;
  } else if (!planner_index(c, c.baseline)) {
    throw InputError("baseline: \"" + c.baseline + "\" is not a planner label of this sweep");
  }
  if (!c.planners[baseline_index(c)].only.everywhere())
    throw InputError("baseline: \"" + c.baseline +
                     "\" has an \"only\" scope; the baseline runs on every map so that every "
                     "planner can be paired with it");
  c.time_limit_s = r.number("time_limit_s", c.time_limit_s, kTimeLimitRange);
  {
    ObjectReader m(optional_object(r, "motion"), "motion.");
    c.motion.line_speed_mps = m.number("line_speed_mps", c.motion.line_speed_mps, 1e-6, 1e6);
    c.motion.node_time_s = m.number("node_time_s", c.motion.node_time_s, 0.0, 1e6);
    c.motion.turn_speed_radps = m.number("turn_speed_radps", c.motion.turn_speed_radps, 1e-6, 1e6);
    m.finish();
  }
  {
    ObjectReader refs(optional_object(r, "references"), "references.");
    c.any_angle_reference = refs.boolean("any_angle", true);
    refs.finish();
  }
  c.threads = static_cast<int>(r.integer("threads", 0, kThreadsRange));
  c.report_path = r.string("report", c.report_path);
  c.runs_path = r.string("runs", c.runs_path);
  if (c.report_path.empty()) throw InputError("report: must not be empty");
  if (r.has("sources")) c.sources = parse_sources(r.raw("sources"), "sources");
  r.finish();
  // The size first: a config too large to hold may be too large to walk cell by cell.
  check_sweep_size(c);
  check_cells(c);
  return c;
}

namespace {

// Line and column of byte `offset` of `text`, both from 1.
std::string line_column(const std::string& text, std::size_t offset) {
  std::size_t line = 1, col = 1;
  for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      col = 1;
    } else {
      ++col;
    }
  }
  return std::to_string(line) + ":" + std::to_string(col);
}

// Byte offset of the opening quote of the n-th object key (from 0) of well-formed JSON `text`:
// a key is the one kind of string followed by ':'.
std::size_t key_offset(const std::string& text, std::size_t n) {
  std::size_t keys = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '"') continue;
    const std::size_t open = i;
    for (++i; i < text.size() && text[i] != '"'; ++i)
      if (text[i] == '\\') ++i;
    std::size_t next = i + 1;
    while (next < text.size() && std::isspace(static_cast<unsigned char>(text[next]))) ++next;
    if (next < text.size() && text[next] == ':' && keys++ == n) return open;
  }
  return text.size();
}

// Parses `text`, refusing a key that appears twice in one object (nlohmann keeps the last one
// silently, so one of two settings would be dropped without a word).
json parse_without_duplicate_keys(const std::string& text, const std::string& path) {
  std::vector<std::set<std::string>> open_objects;
  std::size_t keys_seen = 0;
  std::string duplicate;
  std::size_t duplicate_index = 0;
  const json::parser_callback_t check = [&](int, json::parse_event_t event, json& parsed) {
    if (event == json::parse_event_t::object_start) {
      open_objects.emplace_back();
    } else if (event == json::parse_event_t::object_end) {
      open_objects.pop_back();
    } else if (event == json::parse_event_t::key) {
      const auto& key = parsed.get_ref<const std::string&>();
      if (!open_objects.back().insert(key).second && duplicate.empty()) {
        duplicate = key;
        duplicate_index = keys_seen;
      }
      ++keys_seen;
    }
    return true;
  };
  json j;
  try {
    j = json::parse(text, check);
  } catch (const json::parse_error& e) {
    // nlohmann reports a byte offset (one past the error); the user wants a line and column.
    throw InputError(path + ":" + line_column(text, e.byte == 0 ? 0 : e.byte - 1) +
                     ": malformed JSON (" + e.what() + ")");
  }
  if (!duplicate.empty())
    throw InputError(path + ":" + line_column(text, key_offset(text, duplicate_index)) +
                     ": key \"" + duplicate +
                     "\" appears twice in one object (only one value can hold)");
  return j;
}

}  // namespace

SweepConfig load_config(const std::string& path) {
  const std::string text = read_text_file(path, "config file", std::uintmax_t{64} << 20);
  const json j = parse_without_duplicate_keys(text, path);
  try {
    const std::string folder = std::filesystem::path(path).parent_path().string();
    return parse_config(j, folder.empty() ? "." : folder);
  } catch (const InputError& e) {
    throw InputError(path + ": " + e.what());
  }
}

}  // namespace agv
