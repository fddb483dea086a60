#include "engine/plan/files_read.h"

namespace agv {

void add_plugins_read(const std::vector<PluginRecord>& plugins, std::vector<InputPath>& inputs) {
  for (const auto& p : plugins) inputs.push_back({"plugin library of " + p.name, p.path});
}

std::vector<InputPath> files_read(const SweepConfig& config, const std::string& config_path) {
  std::vector<InputPath> inputs = {{"config file", config_path}};
  add_plugins_read(config.plugins, inputs);
  for (const auto& g : config.generators) {
    if (!g.files) continue;
    for (const auto& f : g.files->files)
      for (const auto& r : f.read) inputs.push_back({r.what, r.path});
  }
  return inputs;
}

}  // namespace agv
