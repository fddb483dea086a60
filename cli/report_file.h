#pragma once
// A report file the command line reads (compare, digest): its text parsed as JSON, or InputError
// (exit 2) naming `what` and the path.

#include <nlohmann/json.hpp>
#include <string>

namespace agv {

nlohmann::json read_report(const std::string& path, const std::string& what);

}  // namespace agv
