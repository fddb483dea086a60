#pragma once
// Named, documented, range-checked parameters of planners and map generators. Each is declared
// once, in a ParamDecls<Options> that binds its name, type, range, default and doc to the field
// of Options it fills (the way OMPL's declareParam ties a name to its setter): from that one
// declaration come the defaults, validation of a config's values (unknown names, wrong types and
// out-of-range values are errors naming the field), `agvbench list`, and the filled Options
// struct. No parameter is ever read back by a second spelling of its name.

#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

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

// Checks a set of declarations, as a plugin hands them over (engine/plan/plugins.cpp): each name a
// word of lower-case letters, digits and '_', no name twice, a known type, finite bounds with min
// <= max (whole numbers for an integer), a non-empty choice list without repeats, and a default
// that its own declaration accepts. Throws InputError naming `who` and the parameter.
void check_param_specs(const std::vector<ParamSpec>& specs, const std::string& who);

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

// The names of a choice parameter and the value each stands for, in the order `list` shows them.
template <class E>
using ChoiceTable = std::vector<std::pair<std::string, E>>;

// Parameters declared once, each bound to the field of Options it fills. `field` is a pointer
// to member (&Options::weight) or a callable returning a reference into Options
// ([](Options& o) -> double& { return o.bspline.sample_step; }); include() adds a group declared
// for a member struct (the post-processing options every grid search shares).
template <class Options>
class ParamDecls {
 public:
  template <class Field>
  ParamDecls& number(std::string name, Field field, double def, double lo, double hi,
                     std::string doc) {
    return add(
        ParamSpec::number(std::move(name), def, lo, hi, std::move(doc)),
        [field](Options& o, const nlohmann::json& v) { std::invoke(field, o) = v.get<double>(); });
  }
  template <class Field>
  ParamDecls& integer(std::string name, Field field, long long def, long long lo, long long hi,
                      std::string doc) {
    return add(ParamSpec::integer(std::move(name), def, lo, hi, std::move(doc)),
               [field](Options& o, const nlohmann::json& v) {
                 auto& target = std::invoke(field, o);
                 target =
                     static_cast<std::remove_reference_t<decltype(target)>>(v.get<long long>());
               });
  }
  template <class Field>
  ParamDecls& boolean(std::string name, Field field, bool def, std::string doc) {
    return add(
        ParamSpec::boolean(std::move(name), def, std::move(doc)),
        [field](Options& o, const nlohmann::json& v) { std::invoke(field, o) = v.get<bool>(); });
  }
  // A choice among named values of E (an enum, or std::string for free-standing names).
  template <class Field, class E>
  ParamDecls& choice(std::string name, Field field, const E& def, ChoiceTable<E> table,
                     std::string doc) {
    std::vector<std::string> names;
    std::string def_name;
    for (const auto& [n, value] : table) {
      names.push_back(n);
      if (value == def && def_name.empty()) def_name = n;
    }
    if (def_name.empty()) throw std::logic_error("parameter " + name + ": default not a choice");
    return add(ParamSpec::choice(std::move(name), def_name, std::move(names), std::move(doc)),
               [field, table = std::move(table)](Options& o, const nlohmann::json& v) {
                 const auto& text = v.get_ref<const std::string&>();
                 for (const auto& [n, value] : table)
                   if (n == text) {
                     std::invoke(field, o) = value;
                     return;
                   }
                 throw std::logic_error("choice not validated: " + text);
               });
  }
  // Every declaration of `group`, filling the member struct `member` of Options.
  template <class Member, class Sub>
  ParamDecls& include(Member member, const ParamDecls<Sub>& group) {
    for (std::size_t i = 0; i < group.specs().size(); ++i) {
      auto set = group.setter(i);
      add(group.specs()[i],
          [member, set](Options& o, const nlohmann::json& v) { set(std::invoke(member, o), v); });
    }
    return *this;
  }

  const std::vector<ParamSpec>& specs() const { return specs_; }
  // Fills every declared field of `base` from a set resolved against specs().
  Options read(const Params& params, Options base = Options()) const {
    for (std::size_t i = 0; i < specs_.size(); ++i)
      setters_[i](base, params.values().at(specs_[i].name));
    return base;
  }
  // Validates `given` (throws InputError naming `where`) and fills the options.
  Options resolve(const nlohmann::json& given, const std::string& where,
                  Options base = Options()) const {
    return read(Params::resolve(specs_, given, where), std::move(base));
  }

  using Setter = std::function<void(Options&, const nlohmann::json&)>;
  const Setter& setter(std::size_t i) const { return setters_[i]; }

 private:
  ParamDecls& add(ParamSpec spec, Setter set) {
    for (const auto& s : specs_)
      if (s.name == spec.name) throw std::logic_error("parameter declared twice: " + spec.name);
    specs_.push_back(std::move(spec));
    setters_.push_back(std::move(set));
    return *this;
  }
  std::vector<ParamSpec> specs_;
  std::vector<Setter> setters_;
};

}  // namespace agv
