#pragma once
// Map sources: the user's own map files as a sweep's generators (`movingai`: .map files with
// their .scen queries; `image`: ROS map_server .yaml, .pgm and .png occupancy images). A config
// names one like a generator, `{"name": "movingai", "params": {"files": [...], ...}}`; each file
// becomes one cell of the sweep, named by the file. The files are read once, when the config is
// loaded (a bad file is an InputError naming it and its line), and every map of a cell is that
// file's grid with one query: a .scen query (`queries: "scen"`) or endpoints drawn by the sweep's
// endpoint rule from the map's own random stream.

#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "core/grid.h"
#include "core/params.h"
#include "core/rng.h"
#include "generators/map_generators.h"
#include "generators/movingai.h"

namespace agv {

enum class QuerySource {
  endpoints,  // maps_per_cell queries per file, drawn by the sweep's endpoint rule
  scen,       // the file's .scen queries: the 0th, Nth, 2Nth... (scen_every), within scen_buckets
};

// A file read for a map, named for messages ("map file", "scenario file of a.map").
struct FileRead {
  std::string what;
  std::string path;
};

struct MapFile {
  std::string name;            // names the cell: the file name, or its path where two share one
  std::string path;            // the path read (the config's folder joined with the match)
  std::string content_hash;    // 16 hex digits over the bytes of every file read for it
  std::vector<FileRead> read;  // every file read for it: the map, then its .scen or image
  Grid grid;
  std::vector<ScenarioQuery> queries;  // queries "scen": the selected queries, in file order
};

struct MapFileSet {
  std::string source;  // the map source's name
  QuerySource queries = QuerySource::endpoints;
  std::vector<MapFile> files;
  nlohmann::json resolved;  // the parameters with their defaults: what the config hash covers
};

struct MapSourceInfo {
  std::string name;
  std::string summary;
  // Its parameters as `agvbench list` shows them (name, type, default, doc).
  std::vector<std::pair<std::string, std::string>> params;
  // Reads `params` ({"files": [...], ...}) against the config's folder `base_dir`; `cell_edge` is
  // the edge of a map whose file does not give one. InputError naming `where`.params.<name>, or
  // the file and line.
  std::function<MapFileSet(const nlohmann::json& params, const std::string& base_dir,
                           double cell_edge, const std::string& where)>
      load;
};

// The registered map sources, in `list` order.
const std::vector<MapSourceInfo>& map_source_registry();
// nullptr when unknown.
const MapSourceInfo* find_map_source(std::string_view name);

// The files `patterns` (a JSON array of paths or glob(3) patterns, relative to base_dir unless
// absolute) match, each pattern's matches sorted; InputError naming `where`[i] for a pattern that
// matches nothing or a file matched twice.
std::vector<std::string> expand_file_patterns(const nlohmann::json& patterns,
                                              const std::string& base_dir,
                                              const std::string& where);

// The checks the maps of `file` would fail under `spec`'s endpoint rule (corners on an obstacle,
// corners not connected under the solvable rule, min_distance beyond the map's diagonal, fewer
// than two free cells): InputError naming the file.
void check_file_endpoints(const MapFile& file, const MapSpec& spec);

// One query on a file's grid.
struct FileQuery {
  Cell start;
  Cell goal;
  int rejections = 0;          // endpoint draws thrown away by require_solvable
  double scen_optimum = -1.0;  // the .scen's optimal length; negative when there is none
};

// Map `map_index` of `file`: its `map_index`-th selected .scen query, or endpoints drawn from
// `rng` by spec's endpoint rule (std::runtime_error when require_solvable fails max_attempts
// draws).
FileQuery file_query(const MapFile& file, QuerySource queries, int map_index, const MapSpec& spec,
                     Rng& rng);

}  // namespace agv
