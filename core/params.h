#pragma once
// Named, documented, range-checked planner parameters (STYLE.md item 5). A planner declares a
// ParamSpec list once; from it come the defaults, validation of a config's values (unknown
// names and out-of-range values are errors naming the field), and `agvbench list`.

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/input_error.h"

namespace agv {

enum class ParamType { number, integer, boolean, choice };

struct ParamSpec {
  std::string name;
  ParamType type = ParamType::number;
  nlohmann::json default_value;
  std::string doc;
  double min = -1e300;  // inclusive, number and integer
  double max = 1e300;
  std::vector<std::string> choices;  // choice only

  static ParamSpec number(std::string name, double def, double lo, double hi, std::string doc);
  static ParamSpec integer(std::string name, long long def, long long lo, long long hi,
                           std::string doc);
  static ParamSpec boolean(std::string name, bool def, std::string doc);
  static ParamSpec choice(std::string name, std::string def, std::vector<std::string> choices,
                          std::string doc);
  nlohmann::json to_json() const;
};

// A validated parameter set: every declared name present, each value of its type and in range.
class Params {
 public:
  Params() = default;
  // Throws InputError naming `where` + "." + the parameter for unknown names, wrong types and
  // out-of-range values. Missing values take their defaults.
  static Params resolve(const std::vector<ParamSpec>& specs, const nlohmann::json& given,
                        const std::string& where);

  double number(const std::string& name) const;
  long long integer(const std::string& name) const;
  bool boolean(const std::string& name) const;
  const std::string& choice(const std::string& name) const;
  // Every parameter with its resolved value, keys sorted (for reports and records).
  const nlohmann::json& values() const { return values_; }

 private:
  const nlohmann::json& at(const std::string& name) const;
  nlohmann::json values_ = nlohmann::json::object();
};

}  // namespace agv
