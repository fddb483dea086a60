#pragma once
// Loading planner plugins (algos/plugin.h; `--plugin PATH` on the command line, "plugins" in a
// config): each shared library is opened once per process with dlopen, its build record checked
// against the engine's, and its planners added to the registry (algos/registry.h), where they are
// configured, validated, measured and reported exactly like the built-in ones. Plugins are loaded
// before any sweep starts and never unloaded. Every failure (not a file, not a shared library,
// an unresolved symbol, no entry point, another plugin ABI, agvbench version or toolchain, a
// planner or plugin name already taken) is an InputError naming the plugin's path: exit 2.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace agv {

// What a report keeps of a plugin: enough to know that a resumed sweep or an isolated worker
// runs the same code.
struct PluginRecord {
  std::string name;
  std::string version;
  std::string path;    // absolute, symbolic links resolved
  std::string sha256;  // of the file's content
  std::string compiler;
  std::vector<std::string> planners;  // in the plugin's order
  // {"name", "version", "path", "sha256"}: the config's "plugins" entry as run.
  nlohmann::json as_run() const;
};

// Loads the plugin at `path` (relative paths from the working directory) unless the same file
// is loaded already; `where` names the setting in messages ("--plugin", "plugins[0]").
const PluginRecord& load_plugin(const std::string& path, const std::string& where);

// A config's "plugins" entry as run: loads the file and refuses it unless its name, version and
// content are still those recorded.
const PluginRecord& load_recorded_plugin(const nlohmann::json& entry, const std::string& where);

// The plugins loaded in this process, sorted by name (a config's "plugins" as run, and `list`).
std::vector<PluginRecord> loaded_plugins();

}  // namespace agv
