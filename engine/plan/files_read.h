#pragma once
// The one list of the files a sweep config makes a command read, so that every command that
// writes (run, merge, export, validate's preview of run) refuses an output onto any of them
// (engine/plan/output_paths.h), not only onto the config it was given.

#include <string>
#include <vector>

#include "engine/plan/output_paths.h"
#include "engine/plan/sweep_config.h"

namespace agv {

// The config file, every plugin loaded in this process (the config's and --plugin's), and every
// file a map source read: each .map with its .scen, each YAML map with the image it names.
std::vector<InputPath> files_read(const SweepConfig& config, const std::string& config_path);

// The plugins' libraries alone (a command without a config: plan with --plugin).
void add_plugins_read(const std::vector<PluginRecord>& plugins, std::vector<InputPath>& inputs);

}  // namespace agv
