#include "engine/cli_params.h"

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
  int x = 0, y = 0;
  char comma = 0;
  int used = 0;
  if (std::sscanf(text.c_str(), "%d %c %d%n", &x, &comma, &y, &used) != 3 || comma != ',' ||
      used != static_cast<int>(text.size()))
    throw InputError(what + ": expected x,y, got \"" + text + "\"");
  return {x, y};
}

}  // namespace agv
