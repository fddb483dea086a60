#pragma once
// Bad user input: a config value, a planner parameter, a map or scenario file. Reported once at
// the boundary with exit code 2; the message names the field or the file and line.

#include <stdexcept>

namespace agv {

class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace agv
