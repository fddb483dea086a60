#include "cli/locate_config.h"

#include <filesystem>

#ifndef AGV_SOURCE_DIR
#define AGV_SOURCE_DIR "."
#endif

namespace agv {

// The default config is found from any working directory: first as given, then in the checkout
// the binary was built from.
std::string locate_config(const std::string& path) {
  namespace fs = std::filesystem;
  if (fs::exists(path) || fs::path(path).is_absolute()) return path;
  const fs::path in_source = fs::path(AGV_SOURCE_DIR) / path;
  if (fs::exists(in_source)) return in_source.string();
  return path;
}

}  // namespace agv
