#pragma once
// A report's fingerprint: the SHA-256 of its deterministic part (engine/outputs/report.h) written
// as compact JSON with sorted keys and shortest round-trip numbers. Two reports have the same
// digest exactly when every non-timing value agrees to the last bit, whichever machine, thread
// count or front-end produced them; tests/golden/ holds the digests results are held to
// (docs/TESTING.md "Golden digests").

#include <nlohmann/json.hpp>
#include <string>

namespace agv {

// 64 lowercase hex digits. Throws InputError naming `name` when `report` is not an agvbench
// report (an object with "tool": "agvbench", a config and cells): a digest of any JSON document
// would match nothing and say nothing.
std::string report_digest(const nlohmann::json& report, const std::string& name);

}  // namespace agv
