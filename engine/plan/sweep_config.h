#pragma once
// A sweep's configuration: what maps, which planners, how many of each; its canonical form (the
// config as run) and hash. Read from JSON by engine/plan/config_loader.h.

#include <algorithm>
#include <cstdint>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "algos/registry.h"
#include "core/collision_model.h"
#include "core/json_reader.h"
#include "engine/judge/metrics.h"
#include "engine/plan/plugins.h"
#include "generators/map_files.h"
#include "generators/map_generators.h"
#include "generators/registry.h"

namespace agv {

// The ranges of the config's numbers that the command line shares: `plan --seed`, `--size`,
// `--density`, `--map-index` and `run --threads` are checked against these very values
// (cli/cli_numbers.h), so a number the config refuses the command line refuses too.
inline constexpr IntRange kSeedRange{0, 1LL << 53};
inline constexpr IntRange kMapSideRange{2, kMaxMapSide};
inline constexpr NumberRange kDensityRange{0.0, 0.95};
inline constexpr IntRange kMapsPerCellRange{1, 10'000'000};
inline constexpr IntRange kMapIndexRange{0, kMapsPerCellRange.hi - 1};
inline constexpr IntRange kThreadsRange{0, 4096};
inline constexpr NumberRange kTimeLimitRange{1e-3, 86400.0};

struct GridSize {
  int width = 0;
  int height = 0;
  auto operator<=>(const GridSize&) const = default;
};

// Where a planner runs when not on every map of the sweep ("only" in the config): a planner
// that costs a hundred times more than a grid search (the fusion simulations) can join a big
// sweep on a subset of its cells and on the first maps of each, and is still paired map by map
// with the baseline, which runs everywhere. An empty list means every value of that axis.
struct PlannerScope {
  std::vector<std::string> generators;
  std::vector<GridSize> sizes;
  std::vector<double> densities;
  int maps_per_cell = 0;  // the first N maps of each cell; 0 = all of them
  bool everywhere() const {
    return generators.empty() && sizes.empty() && densities.empty() && maps_per_cell == 0;
  }
  // Of a listed cell's `maps`, how many the planner runs on (the plan's scoped_maps and the size
  // estimate both count with it).
  int maps_in(int maps) const { return maps_per_cell > 0 ? std::min(maps_per_cell, maps) : maps; }
};

// One generator of the sweep: a name, or {"name": ..., "params": {...}} in the config.
struct GeneratorEntry {
  std::string name;  // registry name; unique within the sweep (it names the cells)
  nlohmann::json params = nlohmann::json::object();    // as given
  nlohmann::json resolved = nlohmann::json::object();  // every shape parameter with its value
  // A map source (generators/map_files.h): its files, read when the config is loaded, one cell
  // each; null for a generator, whose cells are sizes x densities.
  std::shared_ptr<const MapFileSet> files = nullptr;
};

struct PlannerEntry {
  std::string label;  // unique within the sweep; defaults to the registry name
  std::string name;   // registry name
  nlohmann::json params = nlohmann::json::object();  // as given
  nlohmann::json resolved;                           // every parameter with its value
  PlannerScope only;
  // Parameters set looser than the sweep's collision model (the entry is then a labelled
  // variant, judged under the model all the same).
  std::vector<ModelDeviation> looser_than_model;
};

struct SweepConfig {
  std::string name = "sweep";
  std::uint64_t seed = 1;
  std::vector<GeneratorEntry> generators = {{"uniform"}};
  std::vector<GridSize> sizes = {{64, 64}};
  std::vector<double> densities = {0.2};
  int maps_per_cell = 100;
  // What every path of the sweep is judged under, and the default of every planner's own rule
  // and clearance (docs/METRICS.md "Collision model").
  CollisionModel collision;
  MapSpec map;  // endpoints, require_solvable, ...; generator, shape, size, density per cell
  std::vector<PlannerEntry> planners;
  std::string baseline;        // planner label the paired comparisons use
  double time_limit_s = 10.0;  // per run, cooperative
  MotionTimeParams motion;
  // "references": {"any_angle": false} leaves out the any-angle reference (any_angle_ratio is
  // then null): on whole benchmark maps it costs more than the runs it judges (docs/METRICS.md
  // "any_angle_ratio").
  bool any_angle_reference = true;
  // "sources": free text saying where each value comes from (a paper's section or table);
  // echoed in the report's config, not part of the config hash. Empty = none given.
  nlohmann::json sources = nlohmann::json::object();
  // Every plugin loaded in this process when the config was parsed (from "plugins" or the
  // command line's --plugin), sorted by name: the config as run records each one's identity, path
  // and content hash, so the config hash, a resume and an isolated worker know the code that ran.
  std::vector<PluginRecord> plugins;
  // Execution settings: they change how a sweep runs, never what it reports.
  int threads = 0;  // 0 = all hardware threads
  std::string report_path = "reports/out/report.json";
  std::string runs_path;       // JSON Lines of per-run records; empty = none
  std::string base_dir = ".";  // the config file's folder: map sources' files are relative to it
};

// The config as run, every default filled in, execution settings left out: the part of a
// report that the determinism guarantee covers.
// A map source's entry lists its files with their content hashes ("map_files"), so a changed
// map file is another config.
nlohmann::json config_as_run(const SweepConfig& config);

// Two parts of config_as_run, which the loader also checks a stated config as run against (an
// isolation worker's, a report's): a map source's files with their content hashes, and the
// parameters a planner entry sets looser than the collision model.
nlohmann::json map_files_json(const MapFileSet& set);
nlohmann::json looser_json(const std::vector<ModelDeviation>& deviations);

// Stable hash of config_as_run (journal compatibility, task ids), "sources" left out (it is
// commentary). Only the generators the sweep uses enter it, so a generator or parameter added to
// the registry leaves journals valid.
std::string config_hash(const SweepConfig& config);
// The config index of the planner labelled `label`, if there is one.
std::optional<std::size_t> planner_index(const SweepConfig& config, const std::string& label);
// The config index of the baseline, which the loader makes sure is one of the planners (throws
// std::logic_error for a config that did not come through it with one).
std::size_t baseline_index(const SweepConfig& config);

// The same of a config as run as JSON (a report's "config"): the one place the hash is made and
// formatted, 16 hex digits.
std::string config_hash_of(nlohmann::json as_run);

}  // namespace agv
