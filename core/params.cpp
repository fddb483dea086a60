#include "core/params.h"

#include <cmath>
#include <cstdint>
#include <sstream>

#include "core/json_text.h"

namespace agv {

using nlohmann::json;

ParamSpec ParamSpec::number(std::string name, double def, double lo, double hi, std::string doc) {
  ParamSpec s;
  s.name = std::move(name);
  s.type = ParamType::number;
  s.default_value = def;
  s.min = lo;
  s.max = hi;
  s.doc = std::move(doc);
  return s;
}

ParamSpec ParamSpec::integer(std::string name, long long def, long long lo, long long hi,
                             std::string doc) {
  ParamSpec s;
  s.name = std::move(name);
  s.type = ParamType::integer;
  s.default_value = def;
  s.min = static_cast<double>(lo);
  s.max = static_cast<double>(hi);
  s.doc = std::move(doc);
  return s;
}

ParamSpec ParamSpec::boolean(std::string name, bool def, std::string doc) {
  ParamSpec s;
  s.name = std::move(name);
  s.type = ParamType::boolean;
  s.default_value = def;
  s.doc = std::move(doc);
  return s;
}

ParamSpec ParamSpec::choice(std::string name, std::string def, std::vector<std::string> choices,
                            std::string doc) {
  ParamSpec s;
  s.name = std::move(name);
  s.type = ParamType::choice;
  s.default_value = std::move(def);
  s.choices = std::move(choices);
  s.doc = std::move(doc);
  return s;
}

json ParamSpec::to_json() const {
  json j;
  j["name"] = name;
  j["default"] = default_value;
  j["doc"] = doc;
  switch (type) {
    case ParamType::number:
      j["type"] = "number";
      j["min"] = min;
      j["max"] = max;
      break;
    case ParamType::integer:
      j["type"] = "integer";
      j["min"] = static_cast<long long>(min);
      j["max"] = static_cast<long long>(max);
      break;
    case ParamType::boolean:
      j["type"] = "boolean";
      break;
    case ParamType::choice:
      j["type"] = "choice";
      j["choices"] = choices;
      break;
  }
  return j;
}

namespace {

std::string range_text(const ParamSpec& s) {
  std::ostringstream out;
  out << "[" << s.min << ", " << s.max << "]";
  return out.str();
}

json check_value(const ParamSpec& s, const json& v, const std::string& field) {
  switch (s.type) {
    case ParamType::number: {
      if (!v.is_number()) throw InputError(field + ": expected a number, got " + json_text(v));
      const double x = v.get<double>();
      if (!std::isfinite(x) || x < s.min || x > s.max)
        throw InputError(field + ": " + json_text(v) + " is outside " + range_text(s));
      return x;
    }
    case ParamType::integer: {
      if (!v.is_number_integer()) {
        if (v.is_number_float() && std::floor(v.get<double>()) == v.get<double>() &&
            std::abs(v.get<double>()) < 9e15) {
          return check_value(s, json(static_cast<long long>(v.get<double>())), field);
        }
        throw InputError(field + ": expected an integer, got " + json_text(v));
      }
      // Above 2^63 - 1 nlohmann holds an unsigned value that get<long long> would wrap negative.
      if (v.is_number_unsigned() && static_cast<double>(v.get<std::uint64_t>()) > s.max)
        throw InputError(field + ": " + json_text(v) + " is outside " + range_text(s));
      const auto x = v.get<long long>();
      if (static_cast<double>(x) < s.min || static_cast<double>(x) > s.max)
        throw InputError(field + ": " + json_text(v) + " is outside " + range_text(s));
      return x;
    }
    case ParamType::boolean:
      if (!v.is_boolean())
        throw InputError(field + ": expected true or false, got " + json_text(v));
      return v;
    case ParamType::choice: {
      if (!v.is_string()) throw InputError(field + ": expected a string, got " + json_text(v));
      const auto& text = v.get_ref<const std::string&>();
      for (const auto& c : s.choices)
        if (c == text) return v;
      std::string list;
      for (const auto& c : s.choices) list += (list.empty() ? "" : ", ") + c;
      throw InputError(field + ": \"" + text + "\" is not one of: " + list);
    }
  }
  return v;
}

}  // namespace

namespace {

bool valid_param_name(const std::string& name) {
  if (name.empty()) return false;
  for (const char c : name)
    if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_')) return false;
  return true;
}

void check_bounds(const ParamSpec& s, const std::string& field) {
  if (std::isnan(s.min) || std::isnan(s.max)) throw InputError(field + ": a bound is NaN");
  if (s.min > s.max) throw InputError(field + ": its range " + range_text(s) + " is empty");
  if (s.type == ParamType::integer && (std::floor(s.min) != s.min || std::floor(s.max) != s.max))
    throw InputError(field + ": an integer's bounds " + range_text(s) + " are not whole numbers");
}

void check_choices(const ParamSpec& s, const std::string& field) {
  if (s.choices.empty()) throw InputError(field + ": a choice without choices");
  for (std::size_t i = 0; i < s.choices.size(); ++i) {
    if (s.choices[i].empty()) throw InputError(field + ": an empty choice");
    for (std::size_t j = 0; j < i; ++j)
      if (s.choices[j] == s.choices[i])
        throw InputError(field + ": choice \"" + s.choices[i] + "\" listed twice");
  }
}

}  // namespace

void check_param_specs(const std::vector<ParamSpec>& specs, const std::string& who) {
  for (std::size_t i = 0; i < specs.size(); ++i) {
    const ParamSpec& s = specs[i];
    const std::string field = who + ": parameter \"" + s.name + "\"";
    if (!valid_param_name(s.name))
      throw InputError(field + ": a name must be a word of a-z, 0-9 and '_'");
    for (std::size_t j = 0; j < i; ++j)
      if (specs[j].name == s.name) throw InputError(field + ": declared twice");
    switch (s.type) {
      case ParamType::number:
      case ParamType::integer:
        check_bounds(s, field);
        break;
      case ParamType::choice:
        check_choices(s, field);
        break;
      case ParamType::boolean:
        break;
      default:
        throw InputError(field + ": unknown type " + std::to_string(static_cast<int>(s.type)));
    }
    if (s.type != ParamType::choice && !s.choices.empty())
      throw InputError(field + ": choices given for a parameter that is not a choice");
    try {
      check_value(s, s.default_value, field + " default");
    } catch (const InputError& e) {
      throw InputError(std::string(e.what()) + " (its own declaration refuses it)");
    }
  }
}

Params Params::resolve(const std::vector<ParamSpec>& specs, const json& given,
                       const std::string& where) {
  if (!given.is_null() && !given.is_object())
    throw InputError(where + ": parameters must be a JSON object");
  Params p;
  for (const auto& s : specs) p.values_[s.name] = s.default_value;
  if (given.is_object()) {
    for (const auto& [key, value] : given.items()) {
      const ParamSpec* spec = nullptr;
      for (const auto& s : specs)
        if (s.name == key) spec = &s;
      if (spec == nullptr) {
        std::string known;
        for (const auto& s : specs) known += (known.empty() ? "" : ", ") + s.name;
        throw InputError(where + "." + key +
                         ": unknown parameter (known: " + (known.empty() ? "none" : known) + ")");
      }
      p.values_[key] = check_value(*spec, value, where + "." + key);
    }
  }
  return p;
}

const json& Params::at(const std::string& name) const {
  auto it = values_.find(name);
  if (it == values_.end()) throw std::logic_error("planner asked for undeclared parameter " + name);
  return *it;
}

double Params::number(const std::string& name) const { return at(name).get<double>(); }
long long Params::integer(const std::string& name) const { return at(name).get<long long>(); }
bool Params::boolean(const std::string& name) const { return at(name).get<bool>(); }
const std::string& Params::choice(const std::string& name) const {
  return at(name).get_ref<const std::string&>();
}

}  // namespace agv
