#pragma once
// The machine and build a report was made on (docs/ARCHITECTURE.md "Style" item 8). Lives under the
// report's `environment` key: it describes where the numbers came from and is excluded from the
// determinism comparison.

#include <nlohmann/json.hpp>
#include <string>

namespace agv {

// Also the UTC date (ISO 8601) and the load average when it was taken: a busy machine explains
// slow timings, and neither is a result (both live under `environment`, which the determinism
// comparison leaves out).
nlohmann::json environment_json(int threads);

// "2026-12-02T06:40:00Z": the current time in UTC, ISO 8601, to the second.
std::string utc_now_iso8601();

// `agvbench --version`: version, git revision and compiler, one line.
std::string version_text();

}  // namespace agv
