#include "generators/map_files.h"

#include <glob.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

#include "core/connectivity.h"
#include "core/input_error.h"
#include "core/json_reader.h"
#include "core/json_text.h"
#include "core/printable.h"
#include "core/str_cat.h"
#include "core/text_file.h"
#include "generators/occupancy_image.h"

namespace agv {
namespace {

using nlohmann::json;

constexpr int kEndpointTries = 1000;  // as generated maps (generators/map_generators.cpp)
constexpr long long kMaxScenEvery = 1'000'000'000;

std::string hex(std::uint64_t h) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

// The cell names of a source's files: the file name, or the path as matched where two files
// share a name.
std::vector<std::string> cell_names(const std::vector<std::string>& matched,
                                    const std::string& base_dir) {
  std::map<std::string, int> count;
  for (const auto& m : matched) ++count[std::filesystem::path(m).filename().string()];
  std::vector<std::string> names;
  const std::string prefix = base_dir.empty() ? "" : base_dir + "/";
  for (const auto& m : matched) {
    const std::string file = std::filesystem::path(m).filename().string();
    // A name is a cell key in reports, journals and the worker protocol, all JSON: bytes that are
    // not UTF-8 are written \xNN (core/printable.h), the same on every side, so a record of the
    // cell names it as the sweep does (U+FFFD would not round-trip).
    const std::string name = count[file] == 1          ? file
                             : m.rfind(prefix, 0) == 0 ? m.substr(prefix.size())
                                                       : m;
    names.push_back(printable(name, kPathBytes));
  }
  return names;
}

// Every cell as free/blocked, the grid read from a file with cell edge `cell_edge`.
Grid with_cell_edge(const Grid& g, double cell_edge) {
  Grid out(g.width(), g.height(), cell_edge);
  for (int y = 0; y < g.height(); ++y)
    for (int x = 0; x < g.width(); ++x)
      if (g.blocked(x, y)) out.set_blocked(x, y, true);
  return out;
}

std::vector<std::string> read_files_param(ObjectReader& p, const std::string& base_dir,
                                          json& resolved) {
  const json* files = p.get("files");
  if (files == nullptr)
    throw InputError(p.field("files") + ": missing (a list of paths or glob patterns)");
  resolved["files"] = *files;
  return expand_file_patterns(*files, base_dir, p.field("files"));
}

MapFileSet load_movingai(const json& params, const std::string& base_dir, double cell_edge,
                         const std::string& where) {
  ObjectReader p(params, where + ".", where);
  MapFileSet set;
  set.source = "movingai";
  set.resolved = json::object();
  const std::vector<std::string> matched = read_files_param(p, base_dir, set.resolved);
  std::string queries = "endpoints";
  if (const json* q = p.get("queries")) {
    if (!q->is_string() || (*q != "scen" && *q != "endpoints"))
      throw InputError(p.field("queries") + ": " + json_text(*q) +
                       " is not one of: scen, endpoints");
    queries = q->get<std::string>();
  }
  set.queries = queries == "scen" ? QuerySource::scen : QuerySource::endpoints;
  set.resolved["queries"] = queries;
  long long every = 1;
  if (const json* e = p.get("scen_every"))
    every = ObjectReader::check_integer(*e, p.field("scen_every"), 1, kMaxScenEvery);
  long long bucket_lo = 0, bucket_hi = -1;
  if (const json* b = p.get("scen_buckets")) {
    if (!b->is_array() || b->size() != 2)
      throw InputError(p.field("scen_buckets") + ": expected [first, last] bucket numbers");
    bucket_lo =
        ObjectReader::check_integer((*b)[0], p.field("scen_buckets") + "[0]", 0, 1'000'000'000);
    bucket_hi = ObjectReader::check_integer((*b)[1], p.field("scen_buckets") + "[1]", bucket_lo,
                                            1'000'000'000);
    set.resolved["scen_buckets"] = {bucket_lo, bucket_hi};
  }
  if (set.queries != QuerySource::scen && (p.get("scen_every") || p.get("scen_buckets")))
    throw InputError(p.field(p.get("scen_every") ? "scen_every" : "scen_buckets") +
                     ": applies to queries \"scen\" only (the endpoint rule draws the others)");
  if (set.queries == QuerySource::scen) set.resolved["scen_every"] = every;
  p.finish("files, queries, scen_every, scen_buckets");

  const std::vector<std::string> names = cell_names(matched, base_dir);
  for (std::size_t i = 0; i < matched.size(); ++i) {
    MapFile f;
    f.name = names[i];
    f.path = matched[i];
    std::string bytes = read_text_file(f.path, "map file");
    f.read = {{"map file", f.path}};
    f.grid = with_cell_edge(read_map(f.path), cell_edge);
    if (set.queries == QuerySource::scen) {
      const std::string scen = f.path + ".scen";
      f.read.push_back({"scenario file of " + f.path, scen});
      bytes += '\0';
      bytes += read_text_file(scen, "scenario file (" + f.path + " with queries \"scen\")");
      std::vector<ScenarioQuery> in_range;
      for (auto& q : read_scen(scen))
        if (bucket_hi < 0 || (q.bucket >= bucket_lo && q.bucket <= bucket_hi))
          in_range.push_back(std::move(q));
      for (std::size_t k = 0; k < in_range.size(); k += static_cast<std::size_t>(every)) {
        check_scenario_fits(f.grid, in_range[k], scen, f.path);
        f.queries.push_back(std::move(in_range[k]));
      }
      if (f.queries.empty())
        throw InputError(
            scen + ": no query selected (scen_buckets " +
            (bucket_hi < 0 ? std::string("all") : str_cat("[", bucket_lo, ", ", bucket_hi, "]")) +
            ")");
    }
    f.content_hash = hex(stable_hash(bytes));
    set.files.push_back(std::move(f));
  }
  return set;
}

MapFileSet load_image(const json& params, const std::string& base_dir, double cell_edge,
                      const std::string& where) {
  ObjectReader p(params, where + ".", where);
  MapFileSet set;
  set.source = "image";
  set.resolved = json::object();
  const std::vector<std::string> matched = read_files_param(p, base_dir, set.resolved);
  p.finish("files");
  const std::vector<std::string> names = cell_names(matched, base_dir);
  for (std::size_t i = 0; i < matched.size(); ++i) {
    MapFile f;
    f.name = names[i];
    f.path = matched[i];
    OccupancyImage image = read_occupancy_image(f.path, cell_edge);
    std::string bytes = read_text_file(f.path, "map file");
    f.read = {{"map file", f.path}};
    if (image.image_path != f.path) {
      f.read.push_back({"occupancy image named by " + f.path, image.image_path});
      bytes += '\0';
      bytes += read_text_file(image.image_path, "occupancy image (named by " + f.path + ")");
    }
    f.grid = std::move(image.grid);
    f.content_hash = hex(stable_hash(bytes));
    set.files.push_back(std::move(f));
  }
  return set;
}

bool has_glob_chars(const std::string& s) { return s.find_first_of("*?[") != std::string::npos; }

}  // namespace

const std::vector<MapSourceInfo>& map_source_registry() {
  static const std::vector<MapSourceInfo> registry = {
      {"movingai",
       "MovingAI .map files, one cell each, with their .scen queries or the sweep's endpoints",
       {{"files", "list of paths or glob patterns, relative to the config's folder (required)"},
        {"queries",
         "choice: scen | endpoints (default endpoints: maps_per_cell queries per "
         "file by the sweep's endpoint rule; scen: the FILE.map.scen queries)"},
        {"scen_every", "integer >= 1, default 1: the 0th, Nth, 2Nth... query (scen only)"},
        {"scen_buckets", "[first, last] bucket numbers, default all (scen only)"}},
       load_movingai},
      {"image",
       "ROS map_server occupancy images (.yaml with .pgm/.png, or a bare .pgm/.png), one cell each",
       {{"files", "list of paths or glob patterns, relative to the config's folder (required)"}},
       load_image},
  };
  return registry;
}

const MapSourceInfo* find_map_source(std::string_view name) {
  for (const auto& info : map_source_registry())
    if (info.name == name) return &info;
  return nullptr;
}

std::vector<std::string> expand_file_patterns(const json& patterns, const std::string& base_dir,
                                              const std::string& where) {
  if (!patterns.is_array() || patterns.empty())
    throw InputError(where + ": expected a non-empty array of paths or glob patterns");
  std::vector<std::string> out;
  std::map<std::string, std::size_t> seen;  // canonical path -> pattern index
  for (std::size_t i = 0; i < patterns.size(); ++i) {
    const std::string f = str_cat(where, "[", i, "]");
    if (!patterns[i].is_string() || patterns[i].get<std::string>().empty())
      throw InputError(f + ": expected a path or glob pattern");
    const std::string pattern = patterns[i].get<std::string>();
    refuse_nul_strings(patterns[i], f);  // glob() would read a shorter pattern
    const std::string full = std::filesystem::path(pattern).is_absolute() || base_dir.empty()
                                 ? pattern
                                 : base_dir + "/" + pattern;
    std::vector<std::string> matches;
    glob_t g{};
    const int rc = ::glob(full.c_str(), 0, nullptr, &g);
    if (rc == 0)
      for (std::size_t k = 0; k < g.gl_pathc; ++k) matches.emplace_back(g.gl_pathv[k]);
    globfree(&g);
    if (rc == GLOB_NOSPACE)
      throw std::runtime_error(f + ": out of memory expanding \"" + pattern + "\"");
    if (matches.empty())
      throw InputError(f + ": \"" + pattern + "\" matches no file" +
                       (has_glob_chars(pattern) ? "" : " (no such file)") + " (looked for " + full +
                       ")");
    for (const auto& m : matches) {
      std::error_code ec;
      const std::string canonical = std::filesystem::weakly_canonical(m, ec).string();
      const auto [it, added] = seen.emplace(ec ? m : canonical, i);
      if (!added)
        throw InputError(str_cat(f, ": \"", m, "\" is also matched by ", where, "[", it->second,
                                 "] (each file is one cell: name it once)"));
      out.push_back(m);
    }
  }
  return out;
}

void check_file_endpoints(const MapFile& file, const MapSpec& spec) {
  const Grid& g = file.grid;
  if (spec.endpoints == EndpointMode::corners || spec.endpoints == EndpointMode::fixed) {
    // A file map is never redrawn: its corners or fixed cells must be free (and connected) as read.
    const bool fixed = spec.endpoints == EndpointMode::fixed;
    const char* rule = fixed ? "\"fixed\"" : "\"corners\"";
    const Cell start = fixed ? spec.start : Cell{0, g.height() - 1};
    const Cell goal = fixed ? spec.goal : Cell{g.width() - 1, 0};
    for (const auto& [c, what] : {std::pair{start, "start"}, std::pair{goal, "goal"}}) {
      if (c.x < 0 || c.y < 0 || c.x >= g.width() || c.y >= g.height())
        throw InputError(str_cat(file.path, ": map.", what, ": (", c.x, ", ", c.y,
                                 ") is outside the ", g.width(), "x", g.height(), " map"));
      if (g.blocked(c))
        throw InputError(str_cat(file.path, ": map.endpoints ", rule, ": the ", what,
                                 fixed ? "" : " corner", " (", c.x, ", ", c.y, ") is an obstacle"));
    }
    if (spec.require_solvable && !connected(g, start, goal, spec.solvable_rule))
      throw InputError(str_cat(file.path, ": map.endpoints ", rule, ": (", start.x, ", ", start.y,
                               ") and (", goal.x, ", ", goal.y, ") are not connected under ",
                               to_string(spec.solvable_rule), " (map.require_solvable)"));
    return;
  }
  const double diagonal = std::hypot(g.width() - 1.0, g.height() - 1.0);
  if (spec.min_distance > diagonal)
    throw InputError(str_cat("map.min_distance: ", spec.min_distance, " is outside [0, ", diagonal,
                             "] (the corner-to-corner distance of ", file.path, ", ", g.width(),
                             "x", g.height(), ")"));
  if (g.free_count() < 2) throw InputError(file.path + ": fewer than two free cells");
}

FileQuery file_query(const MapFile& file, QuerySource queries, int map_index, const MapSpec& spec,
                     Rng& rng) {
  const Grid& g = file.grid;
  if (queries == QuerySource::scen) {
    const ScenarioQuery& q = file.queries.at(static_cast<std::size_t>(map_index));
    return {q.start, q.goal, 0, q.optimal_length};
  }
  if (spec.endpoints == EndpointMode::corners)
    return {{0, g.height() - 1}, {g.width() - 1, 0}, 0, -1.0};
  if (spec.endpoints == EndpointMode::fixed) return {spec.start, spec.goal, 0, -1.0};
  // Random endpoints as on generated maps: two distinct free cells at least min_distance apart,
  // redrawn while require_solvable finds them unconnected (each failed draw a rejection).
  std::vector<int> free;
  free.reserve(static_cast<std::size_t>(g.free_count()));
  for (int y = 0; y < g.height(); ++y)
    for (int x = 0; x < g.width(); ++x)
      if (!g.blocked(x, y)) free.push_back(y * g.width() + x);
  const auto n = static_cast<std::uint32_t>(free.size());
  const double min_sq = spec.min_distance * spec.min_distance;
  ConnectivityScratch scratch;
  for (int attempt = 0; attempt < spec.max_attempts; ++attempt) {
    for (int t = 0; t < kEndpointTries; ++t) {
      const int a = free[rng.below(n)];
      const int b = free[rng.below(n)];
      if (a == b) continue;
      const std::int64_t dx = a % g.width() - b % g.width();
      const std::int64_t dy = a / g.width() - b / g.width();
      if (static_cast<double>(dx * dx + dy * dy) < min_sq) continue;
      const Cell start{a % g.width(), a / g.width()};
      const Cell goal{b % g.width(), b / g.width()};
      if (spec.require_solvable && !connected(g, start, goal, spec.solvable_rule, scratch)) break;
      return {start, goal, attempt, -1.0};
    }
  }
  throw std::runtime_error(str_cat("random endpoints on ", file.path,
                                   ": no two free cells min_distance = ", spec.min_distance,
                                   " apart", spec.require_solvable ? " and connected" : "",
                                   " found in ", spec.max_attempts, " draws"));
}

}  // namespace agv
