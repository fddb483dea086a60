#include "cli/cli_params.h"

#include "cli/cli_numbers.h"

namespace agv {

namespace {

std::pair<std::string, nlohmann::json> split_param(const std::string& text,
                                                   const std::string& option = "--param") {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError(option + " " + text + ": expected KEY=VALUE");
  std::string key = text.substr(0, eq);
  std::string value = text.substr(eq + 1);
  nlohmann::json v = nlohmann::json::parse(value, nullptr, false);
  if (v.is_discarded() || v.is_object() || v.is_array()) v = value;
  return {key, v};
}

bool declares(const std::vector<ParamSpec>& specs, const std::string& key) {
  for (const auto& s : specs)
    if (s.name == key) return true;
  return false;
}

}  // namespace

nlohmann::json cli_params_for(const PlannerInfo& info, const std::vector<std::string>& params) {
  nlohmann::json out = nlohmann::json::object();
  for (const auto& p : params) {
    auto [key, value] = split_param(p);
    if (declares(info.params, key)) out[key] = value;
  }
  return out;
}

void check_cli_params(const std::vector<const PlannerInfo*>& planners,
                      const std::vector<std::string>& params) {
  for (const auto& p : params) {
    const auto key = split_param(p).first;
    bool any = false;
    for (const auto* info : planners) any = any || declares(info->params, key);
    if (!any) throw InputError("--param " + key + ": no selected planner has this parameter");
  }
}

nlohmann::json cli_generator_params(const GeneratorInfo& info,
                                    const std::vector<std::string>& params) {
  nlohmann::json out = nlohmann::json::object();
  for (const auto& p : params) {
    auto [key, value] = split_param(p, "--gen-param");
    if (!declares(info.params, key)) {
      std::string known;
      for (const auto& s : info.params) known += (known.empty() ? "" : ", ") + s.name;
      throw InputError("--gen-param " + key + ": generator " + info.name +
                       " has no such parameter (" +
                       (known.empty() ? std::string("it has none") : "known: " + known) + ")");
    }
    out[key] = value;
  }
  return out;
}

Cell parse_cell(const std::string& text, const std::string& what) {
  const auto comma = text.find(',');
  if (comma == std::string::npos) throw InputError(what + ": expected x,y, got \"" + text + "\"");
  // Beyond the largest grid a cell is outside every map; the grid check then says so.
  constexpr IntRange kCoordinate{0, kMaxMapSide};
  return {static_cast<int>(parse_cli_integer(text.substr(0, comma), what + " (x)", kCoordinate)),
          static_cast<int>(parse_cli_integer(text.substr(comma + 1), what + " (y)", kCoordinate))};
}

}  // namespace agv
