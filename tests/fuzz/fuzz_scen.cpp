// libFuzzer harness for the MovingAI .scen reader: arbitrary bytes either parse or throw
// InputError. Every parsed query obeys the reader's documented bounds, and check_scenario_fits
// against a small map either accepts it or throws InputError.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>

#include "generators/movingai.h"

namespace {

[[noreturn]] void finding(const char* what, int line) {
  std::fprintf(stderr, "fuzz_scen: query at line %d: %s\n", line, what);
  std::abort();
}

const agv::Grid& small_map() {
  static const agv::Grid grid = [] {
    agv::Grid g(8, 6);
    g.set_blocked(3, 2, true);
    g.set_blocked(4, 2, true);
    return g;
  }();
  return grid;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  std::vector<agv::ScenarioQuery> queries;
  try {
    std::istringstream in(bytes);
    queries = agv::parse_scen(in, "fuzz.scen");
  } catch (const agv::InputError&) {
    return 0;
  }
  for (const auto& q : queries) {
    if (q.map_width < 1 || q.map_height < 1) finding("map size below 1", q.line);
    if (q.start.x < 0 || q.start.y < 0 || q.start.x >= q.map_width || q.start.y >= q.map_height)
      finding("start outside the declared map", q.line);
    if (q.goal.x < 0 || q.goal.y < 0 || q.goal.x >= q.map_width || q.goal.y >= q.map_height)
      finding("goal outside the declared map", q.line);
    if (!(q.optimal_length >= 0.0)) finding("negative or NaN optimal length", q.line);
    if (q.line < 2) finding("query before the version line", q.line);
    try {
      agv::check_scenario_fits(small_map(), q, "fuzz.scen");
    } catch (const agv::InputError&) {
    }
  }
  return 0;
}
