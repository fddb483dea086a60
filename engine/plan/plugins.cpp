#include "engine/plan/plugins.h"

#include <dlfcn.h>

#include <algorithm>
#include <cctype>
#include <deque>
#include <filesystem>
#include <set>

#include "algos/plugin.h"
#include "algos/registry.h"
#include "core/input_error.h"
#include "core/json_text.h"
#include "core/text_file.h"
#include "engine/system/elf_shape.h"
#include "engine/system/exit_guard.h"
#include "engine/system/sha256.h"

namespace agv {

namespace {

// Loaded plugins in load order; a deque keeps the returned references stable.
std::deque<PluginRecord>& registry() {
  static std::deque<PluginRecord> plugins;
  return plugins;
}

bool valid_plugin_name(const std::string& name) {
  if (name.empty()) return false;
  for (const char c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-' && c != '.')
      return false;
  return true;
}

// A planner's name is an identifier (it names config entries, report keys, file names of the
// pictures and HTML ids): a letter, then letters, digits, '_' and '-'.
bool valid_planner_name(const std::string& name) {
  if (name.empty() || !std::isalpha(static_cast<unsigned char>(name[0]))) return false;
  for (const char c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-') return false;
  return true;
}

std::string text_or(const char* text, const char* fallback) {
  return text == nullptr ? fallback : text;
}

// The plain-C build record against the engine's own (the same macros, expanded here).
void check_build(const AgvPluginBuild& build, const std::string& who) {
  if (build.abi != AGVBENCH_PLUGIN_ABI)
    throw InputError(who + ": built for plugin ABI " + std::to_string(build.abi) +
                     "; this agvbench loads ABI " + std::to_string(AGVBENCH_PLUGIN_ABI) +
                     " (rebuild it against this agvbench)");
  const std::string version = text_or(build.agvbench_version, "(none)");
  if (version != AGVBENCH_VERSION)
    throw InputError(who + ": built against agvbench " + version + "; this is agvbench " +
                     AGVBENCH_VERSION + " (rebuild it against this version's installed package)");
  const std::string toolchain = text_or(build.toolchain, "(none)");
  if (toolchain != AGVBENCH_PLUGIN_TOOLCHAIN)
    throw InputError(who + ": built with " + toolchain + "; this agvbench was built with " +
                     AGVBENCH_PLUGIN_TOOLCHAIN +
                     " (C++ objects cross the boundary: the compiler and standard library must "
                     "match)");
}

// What a planner declares beyond its name: its parameters (core/params.h check_param_specs) and
// its work counters (each one of algos/planner.h WorkCounters', once).
void check_declarations(const PlannerInfo& info, const std::string& who) {
  check_param_specs(info.params, who);
  std::set<std::string> counters;
  for (const auto& [name, doc] : info.counters) {
    if (std::find(kWorkCounterNames.begin(), kWorkCounterNames.end(), name) ==
        kWorkCounterNames.end()) {
      std::string known;
      for (const char* k : kWorkCounterNames) known += (known.empty() ? "" : ", ") + std::string(k);
      throw InputError(who + ": work counter \"" + name + "\" is not one the engine knows (" +
                       known + ")");
    }
    if (!counters.insert(name).second)
      throw InputError(who + ": work counter \"" + name + "\" declared twice");
  }
}

// The plugin's planners, each checked, none registered yet.
std::vector<PlannerInfo> planners_of(const AgvPlugin& plugin, const std::string& who) {
  std::vector<PlannerInfo> planners;
  if (plugin.add_planners == nullptr) throw InputError(who + ": add_planners is null");
  const std::string what = who + "'s add_planners";
  const ForeignCodeScope foreign(what.c_str());
  try {
    plugin.add_planners(&planners);
  } catch (const std::exception& e) {
    throw InputError(who + ": add_planners failed: " + e.what());
  } catch (...) {
    throw InputError(who + ": add_planners threw something that is not a std::exception");
  }
  if (planners.empty()) throw InputError(who + ": hands over no planner");
  std::set<std::string> names;
  for (auto& info : planners) {
    if (info.name.empty() || info.make == nullptr)
      throw InputError(who + ": a planner without a name or a make function");
    if (!valid_planner_name(info.name))
      throw InputError(who + ": planner name \"" + info.name +
                       "\" is not an identifier (a letter, then letters, digits, '_' and '-')");
    if (!names.insert(info.name).second)
      throw InputError(who + ": planner \"" + info.name + "\" handed over twice");
    check_declarations(info, who + ": planner \"" + info.name + "\"");
    info.plugin = plugin.name;
  }
  return planners;
}

// The plugin's entry point, whatever it throws turned into an InputError naming the plugin.
const AgvPlugin* call_entry(AgvPluginEntry entry, const std::string& who) {
  const std::string what = who + "'s " AGVBENCH_PLUGIN_ENTRY;
  const ForeignCodeScope foreign(what.c_str());
  try {
    return entry();
  } catch (const std::exception& e) {
    throw InputError(who + ": " AGVBENCH_PLUGIN_ENTRY " failed: " + e.what());
  } catch (...) {
    throw InputError(who + ": " AGVBENCH_PLUGIN_ENTRY
                           " threw something that is not a std::exception");
  }
}

const PluginRecord* find_loaded(const std::string& path) {
  for (const auto& p : registry())
    if (p.path == path) return &p;
  return nullptr;
}

}  // namespace

nlohmann::json PluginRecord::as_run() const {
  return {{"name", name}, {"version", version}, {"path", path}, {"sha256", sha256}};
}

const PluginRecord& load_plugin(const std::string& path, const std::string& where) {
  namespace fs = std::filesystem;
  require_regular_file(path, where);
  std::error_code ec;
  const std::string canonical = fs::canonical(path, ec).string();
  if (ec) throw InputError(where + " \"" + path + "\": " + ec.message());
  if (const PluginRecord* loaded = find_loaded(canonical)) return *loaded;
  const std::string who = where + " \"" + path + "\"";

  const std::string bytes = read_text_file(canonical, where, std::uintmax_t{1} << 32);
  check_elf_shape(bytes, who);
  // RTLD_NOW: an unresolved symbol is an error here, never a crash in the middle of a sweep.
  // Never closed: its planners live as long as the process.
  void* handle = ::dlopen(canonical.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr)
    throw InputError(who + ": cannot be loaded: " + text_or(::dlerror(), "unknown dlopen error"));
  void* symbol = ::dlsym(handle, AGVBENCH_PLUGIN_ENTRY);
  if (symbol == nullptr)
    throw InputError(who + ": no entry point " AGVBENCH_PLUGIN_ENTRY
                           " (not an agvbench plugin, or one for another plugin ABI)");
  const AgvPlugin* plugin = call_entry(reinterpret_cast<AgvPluginEntry>(symbol), who);
  if (plugin == nullptr) throw InputError(who + ": " AGVBENCH_PLUGIN_ENTRY " returned null");
  check_build(plugin->build, who);

  PluginRecord record;
  record.name = text_or(plugin->name, "");
  if (!valid_plugin_name(record.name))
    throw InputError(who + ": plugin name \"" + record.name +
                     "\" is not a word of letters, digits, '_', '-' and '.'");
  for (const auto& other : registry())
    if (other.name == record.name)
      throw InputError(who + ": plugin name \"" + record.name + "\" is taken by \"" + other.path +
                       "\"");
  const std::string named = who + " (\"" + record.name + "\")";
  record.version = text_or(plugin->version, "");
  record.path = canonical;
  record.sha256 = sha256_hex(bytes);
  record.compiler = text_or(plugin->build.compiler, "");
  std::vector<PlannerInfo> planners = planners_of(*plugin, named);
  // Every clash before any planner is added: a refused plugin leaves the registry as it was.
  const std::vector<const PlannerInfo*> known = all_planners();
  for (const auto& info : planners) {
    record.planners.push_back(info.name);
    for (const auto* other : known)
      if (other->name == info.name)
        throw InputError(named + ": planner \"" + info.name + "\" clashes with " +
                         (other->plugin.empty() ? std::string("the built-in planner")
                                                : "plugin \"" + other->plugin + "\"'s planner"));
  }
  try {
    for (auto& info : planners) add_plugin_planner(std::move(info));
  } catch (const InputError& e) {
    throw InputError(named + ": " + e.what());
  }
  return registry().emplace_back(std::move(record));
}

const PluginRecord& load_recorded_plugin(const nlohmann::json& entry, const std::string& where) {
  if (!entry.is_object() || !entry.contains("path") || !entry["path"].is_string())
    throw InputError(where + ": expected a path or {\"path\": ..., \"sha256\": ...}");
  const PluginRecord& loaded = load_plugin(entry["path"].get<std::string>(), where);
  for (const char* key : {"name", "version", "sha256"}) {
    if (!entry.contains(key)) continue;
    const nlohmann::json have = loaded.as_run()[key];
    if (entry[key] != have)
      throw InputError(where + " \"" + loaded.path + "\": its " + key + " is " + json_text(have) +
                       ", the config recorded " + json_text(entry[key]) +
                       " (the file changed since the sweep was configured)");
  }
  for (const auto& [key, value] : entry.items())
    if (key != "path" && key != "name" && key != "version" && key != "sha256")
      throw InputError(where + "." + key + ": unknown key (known: path, name, version, sha256)");
  return loaded;
}

std::vector<PluginRecord> loaded_plugins() {
  std::vector<PluginRecord> out(registry().begin(), registry().end());
  std::sort(out.begin(), out.end(),
            [](const PluginRecord& a, const PluginRecord& b) { return a.name < b.name; });
  return out;
}

}  // namespace agv
