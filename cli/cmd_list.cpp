// `agvbench list`: the planner and generator registries, as text or as one JSON object.
#include <cstdio>
#include <iostream>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "algos/registry.h"
#include "cli/command.h"
#include "core/input_error.h"
#include "core/json_text.h"
#include "engine/plan/catalogue.h"
#include "engine/plan/plugins.h"
#include "generators/map_files.h"
#include "generators/registry.h"

namespace agv {

namespace {

// `list NAME... [--brief]`: only the named planners or generators (unknown: InputError);
// json: one object {"planners": [...], "generators": [...], "map_sources": [...]}.
struct ListOptions {
  bool json = false;
  bool brief = false;
  std::vector<std::string> names;
};

void print_params(const std::vector<ParamSpec>& params) {
  for (const auto& p : params) {
    const auto j = p.to_json();
    std::cout << "    " << p.name << " = " << json_text(p.default_value);
    if (p.type == ParamType::choice) {
      std::string list;
      for (const auto& c : p.choices) list += (list.empty() ? "" : "|") + c;
      std::cout << "  (" << list << ")";
    } else if (p.type != ParamType::boolean) {
      std::cout << "  [" << json_text(j["min"]) << ", " << json_text(j["max"]) << "]";
    }
    std::cout << "\n        " << p.doc << "\n";
  }
}

// "NAME VERSION (PATH, sha256 HASH)" of a loaded plugin.
std::string plugin_line(const std::string& name) {
  for (const auto& p : loaded_plugins())
    if (p.name == name)
      return p.name + " " + p.version + " (" + p.path + ", sha256 " + p.sha256 + ")";
  return name;
}

}  // namespace

namespace {

// The names asked for, each a planner or a generator; empty = all of them.
struct Selection {
  std::set<std::string> names;
  bool all = true;
  bool has(const std::string& name) const { return all || names.count(name) > 0; }
};

Selection select(const std::vector<std::string>& names) {
  Selection s;
  s.all = names.empty();
  for (const auto& name : names) {
    bool known = find_planner(name) != nullptr;
    for (const auto& g : generator_registry()) known = known || g.name == name;
    for (const auto& m : map_source_registry()) known = known || m.name == name;
    if (!known)
      throw InputError("list: \"" + name +
                       "\" is neither a planner, a generator nor a map source (agvbench list "
                       "--brief names them)");
    s.names.insert(name);
  }
  return s;
}

nlohmann::json selected(const nlohmann::json& entries, const Selection& s) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& e : entries)
    if (s.has(e.at("name").get<std::string>())) out.push_back(e);
  return out;
}

int command_list(const ListOptions& options) {
  const Selection only = select(options.names);
  if (options.json) {
    nlohmann::json doc = catalogue_json();
    for (auto& [key, entries] : doc.items()) entries = selected(entries, only);
    // Only when plugins are loaded (--plugin), so the plain listing keeps its shape.
    if (const auto plugins = loaded_plugins(); !plugins.empty()) {
      doc["plugins"] = nlohmann::json::array();
      for (const auto& p : plugins) {
        nlohmann::json entry = p.as_run();
        entry["compiler"] = p.compiler;
        entry["planners"] = p.planners;
        doc["plugins"].push_back(std::move(entry));
      }
    }
    std::cout << json_text(doc, 2) << "\n";
    return 0;
  }
  if (options.brief) {
    for (const auto* info : all_planners())
      if (only.has(info->name))
        std::printf("planner    %-24s %-12s %s\n", info->name.c_str(), to_string(info->kind),
                    info->summary.c_str());
    for (const auto& info : generator_registry())
      if (only.has(info.name))
        std::printf("generator  %-24s %-12s %s\n", info.name.c_str(), "", info.summary.c_str());
    for (const auto& info : map_source_registry())
      if (only.has(info.name))
        std::printf("map source %-24s %-12s %s\n", info.name.c_str(), "", info.summary.c_str());
    return 0;
  }
  bool any_planner = false;
  for (const auto* info : all_planners()) any_planner = any_planner || only.has(info->name);
  if (any_planner) std::cout << "planners:\n\n";
  for (const auto* planner : all_planners()) {
    const PlannerInfo& info = *planner;
    if (!only.has(info.name)) continue;
    std::cout << info.name << "  -  " << info.summary << "\n    source: " << info.source;
    if (!info.plugin.empty()) std::cout << "\n    plugin: " << plugin_line(info.plugin);
    for (const auto& [name, meaning] : info.counters)
      std::cout << "\n    " << name << ": " << meaning;
    std::cout << (info.stochastic ? "\n    stochastic: draws from the run's RNG" : "") << "\n";
    print_params(info.params);
    std::cout << "\n";
  }
  bool any_generator = false;
  for (const auto& info : generator_registry())
    any_generator = any_generator || only.has(info.name);
  if (any_generator)
    std::cout << "generators (a config's \"generators\" entry: a name or {\"name\": ..., "
                 "\"params\": {...}}):\n\n";
  for (const auto& info : generator_registry()) {
    if (!only.has(info.name)) continue;
    std::cout << info.name << "  -  " << info.summary << "\n";
    print_params(info.params);
    std::cout << "\n";
  }
  bool any_source = false;
  for (const auto& info : map_source_registry()) any_source = any_source || only.has(info.name);
  if (any_source)
    std::cout << "map sources (the user's map files, one cell each; a \"generators\" entry "
                 "{\"name\": ..., \"params\": {\"files\": [...]}}):\n\n";
  for (const auto& info : map_source_registry()) {
    if (!only.has(info.name)) continue;
    std::cout << info.name << "  -  " << info.summary << "\n";
    for (const auto& [name, doc] : info.params) std::cout << "    " << name << ": " << doc << "\n";
    std::cout << "\n";
  }
  return 0;
}

}  // namespace

Command add_list_command(CLI::App& app) {
  auto options = std::make_shared<ListOptions>();
  auto* sub =
      app.add_subcommand("list", "list planners and map generators, their parameters and defaults");
  sub->add_flag("--json", options->json,
                "print the registries as one JSON object {planners, generators}");
  sub->add_option("names", options->names, "only these planners or generators");
  sub->add_flag("--brief", options->brief, "one line per planner and generator");
  return {sub, [options] { return command_list(*options); }};
}
}  // namespace agv
