#pragma once
// A config file named on the command line, found from any working directory.

#include <string>

namespace agv {

// As given when it exists (or is absolute), else in the checkout the binary was built from.
std::string locate_config(const std::string& path);

}  // namespace agv
