#pragma once
// The machine and build a report was made on (docs/ARCHITECTURE.md "Style" item 8). Lives under the
// report's `environment` key: it describes where the numbers came from and is excluded from the
// determinism comparison.

#include <nlohmann/json.hpp>

namespace agv {

nlohmann::json environment_json(int threads);

}  // namespace agv
