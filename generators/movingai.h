#pragma once
// MovingAI benchmark formats (movingai.com/benchmarks/formats.html): `.map` reader and writer,
// `.scen` reader. Readers accept CRLF, trailing blank lines and a map column holding a path;
// malformed input throws InputError naming the file and line ("FILE:LINE: what is wrong").
// Limits: a map side is at most kMaxMapSide (core/grid.h: 8192) cells, as every map source.

#include <iosfwd>
#include <string>
#include <vector>

#include "core/grid.h"
#include "core/input_error.h"

namespace agv {

// '.' and 'G' are passable; '@', 'O', 'T', 'S', 'W' are obstacles.
Grid read_map(const std::string& path);
Grid parse_map(std::istream& in, const std::string& name);  // name: for messages
void write_map(const Grid& grid, std::ostream& out);
void write_map_file(const Grid& grid, const std::string& path);

struct ScenarioQuery {
  int bucket = 0;
  std::string map;  // as written in the file
  int map_width = 0;
  int map_height = 0;
  Cell start;
  Cell goal;
  double optimal_length = 0.0;
  int line = 0;  // 1-based line in the scenario file, for messages
};

std::vector<ScenarioQuery> read_scen(const std::string& path);
std::vector<ScenarioQuery> parse_scen(std::istream& in, const std::string& name);

// Throws InputError "SCEN:LINE: ..." when the query's declared map size differs from the grid,
// or its start or goal lies outside the grid or on an obstacle, or (given `map_path`, the map
// file the queries are for) its map column names another file. `scen_name` names the file.
void check_scenario_fits(const Grid& grid, const ScenarioQuery& query, const std::string& scen_name,
                         const std::string& map_path = "");

}  // namespace agv
