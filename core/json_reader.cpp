#include "core/json_reader.h"

#include <cmath>
#include <cstdint>
#include <sstream>
#include <utility>

#include "core/input_error.h"
#include "core/json_text.h"

namespace agv {

using nlohmann::json;

void refuse_nul_strings(const json& j, const std::string& root) {
  const auto refuse = [&root](const std::string& what) {
    throw InputError((root.empty() ? std::string("config") : root) + ": " + what +
                     " holds a NUL character (\\u0000), which no name, label or path can hold");
  };
  if (j.is_string()) {
    const auto& text = j.get_ref<const std::string&>();
    if (text.find('\0') != std::string::npos) refuse(json_text(text));
  } else if (j.is_array()) {
    for (std::size_t i = 0; i < j.size(); ++i)
      refuse_nul_strings(j[i], root + "[" + std::to_string(i) + "]");
  } else if (j.is_object()) {
    for (const auto& [key, value] : j.items()) {
      if (key.find('\0') != std::string::npos) refuse("key " + json_text(key));
      refuse_nul_strings(value, root.empty() ? key : root + "." + key);
    }
  }
}

ObjectReader::ObjectReader(const json& j, std::string prefix, const std::string& name)
    : j_(j), where_(std::move(prefix)) {
  if (!j_.is_object()) throw InputError(name + ": expected a JSON object");
}

bool ObjectReader::has(const std::string& key) {
  seen_.insert(key);
  return j_.contains(key);
}

const json& ObjectReader::raw(const std::string& key) {
  seen_.insert(key);
  return j_.at(key);
}

const json* ObjectReader::get(const std::string& key) {
  seen_.insert(key);
  return j_.contains(key) ? &j_.at(key) : nullptr;
}

double ObjectReader::number(const std::string& key, double def, double lo, double hi) {
  if (!has(key)) return def;
  return check_number(j_.at(key), field(key), lo, hi);
}

long long ObjectReader::integer(const std::string& key, long long def, long long lo, long long hi) {
  if (!has(key)) return def;
  return check_integer(j_.at(key), field(key), lo, hi);
}

bool ObjectReader::boolean(const std::string& key, bool def) {
  if (!has(key)) return def;
  const json& v = j_.at(key);
  if (!v.is_boolean()) throw InputError(field(key) + ": expected true or false");
  return v.get<bool>();
}

std::string ObjectReader::string(const std::string& key, const std::string& def) {
  if (!has(key)) return def;
  const json& v = j_.at(key);
  if (!v.is_string()) throw InputError(field(key) + ": expected a string");
  return v.get<std::string>();
}

std::string ObjectReader::choice(const std::string& key, const std::string& def,
                                 const std::vector<std::string>& choices) {
  std::string v = string(key, def);
  for (const auto& c : choices)
    if (c == v) return v;
  std::string list;
  for (const auto& c : choices) list += (list.empty() ? "" : ", ") + c;
  throw InputError(field(key) + ": \"" + v + "\" is not one of: " + list);
}

void ObjectReader::finish(const std::string& known) const {
  for (const auto& [key, value] : j_.items()) {
    (void)value;
    if (seen_.count(key)) continue;
    if (known.empty()) throw InputError(field(key) + ": unknown field");
    throw InputError(field(key) + ": unknown field (known: " + known + ")");
  }
}

double ObjectReader::check_number(const json& v, const std::string& field, double lo, double hi) {
  if (!v.is_number()) throw InputError(field + ": expected a number, got " + json_text(v));
  const double x = v.get<double>();
  if (!std::isfinite(x) || x < lo || x > hi) {
    std::ostringstream msg;
    msg << field << ": " << json_text(v) << " is outside [" << lo << ", " << hi << "]";
    throw InputError(msg.str());
  }
  return x;
}

long long ObjectReader::check_integer(const json& v, const std::string& field, long long lo,
                                      long long hi) {
  if (!v.is_number_integer())
    throw InputError(field + ": expected an integer, got " + json_text(v));
  const std::string outside = field + ": " + json_text(v) + " is outside [" + std::to_string(lo) +
                              ", " + std::to_string(hi) + "]";
  // Above 2^63 - 1 nlohmann holds an unsigned value that get<long long> would wrap negative.
  if (v.is_number_unsigned() && v.get<std::uint64_t>() > static_cast<std::uint64_t>(hi))
    throw InputError(outside);
  const auto x = v.get<long long>();
  if (x < lo || x > hi) throw InputError(outside);
  return x;
}

}  // namespace agv
