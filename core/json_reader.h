#pragma once
// The one strict reader of JSON objects: every field read once, checked for type and range, and
// any field nobody asked for refused, each failure an InputError naming the field. A config's
// objects (engine/plan/config_loader.cpp) and a map source's parameters (generators/map_files.cpp)
// are read with it.

#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

namespace agv {

// Inclusive ranges of a setting's numbers (the config's, shared by the command line).
struct IntRange {
  long long lo = 0;
  long long hi = 0;
};
struct NumberRange {
  double lo = 0.0;
  double hi = 0.0;
};

// Refuses a string (a key or a value, at any depth) holding a NUL character: names, labels and
// paths end at their first NUL wherever they meet the system or a C string, so one would be read
// as a shorter one. The InputError names the field, `root` first ("" for a whole config:
// "generators[0].files[1]").
void refuse_nul_strings(const nlohmann::json& j, const std::string& root);

// `prefix` goes before every field name in a message ("map." -> "map.endpoints: ..."); `name`
// names the object itself when it is not one (default: the prefix).
class ObjectReader {
 public:
  ObjectReader(const nlohmann::json& j, const std::string& prefix)
      : ObjectReader(j, prefix, prefix) {}
  ObjectReader(const nlohmann::json& j, std::string prefix, const std::string& name);

  bool has(const std::string& key);
  const nlohmann::json& raw(const std::string& key);
  // The field, or nullptr when absent.
  const nlohmann::json* get(const std::string& key);
  std::string field(const std::string& key) const { return where_ + key; }

  // Each returns `def` when the field is absent.
  double number(const std::string& key, double def, double lo, double hi);
  double number(const std::string& key, double def, NumberRange range) {
    return number(key, def, range.lo, range.hi);
  }
  long long integer(const std::string& key, long long def, long long lo, long long hi);
  long long integer(const std::string& key, long long def, IntRange range) {
    return integer(key, def, range.lo, range.hi);
  }
  bool boolean(const std::string& key, bool def);
  std::string string(const std::string& key, const std::string& def);
  std::string choice(const std::string& key, const std::string& def,
                     const std::vector<std::string>& choices);

  // Refuses every field not asked for; `known`, when given, lists the ones there are.
  void finish(const std::string& known = "") const;

  // A value checked alone, `field` naming it.
  static double check_number(const nlohmann::json& v, const std::string& field, double lo,
                             double hi);
  static double check_number(const nlohmann::json& v, const std::string& field, NumberRange range) {
    return check_number(v, field, range.lo, range.hi);
  }
  static long long check_integer(const nlohmann::json& v, const std::string& field, long long lo,
                                 long long hi);
  static long long check_integer(const nlohmann::json& v, const std::string& field,
                                 IntRange range) {
    return check_integer(v, field, range.lo, range.hi);
  }

 private:
  const nlohmann::json& j_;
  std::string where_;
  std::set<std::string> seen_;
};

}  // namespace agv
