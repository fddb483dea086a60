#pragma once
// A sweep sink (engine/outputs/sweep_sink.h) that could not keep what it was handed: the sweep
// stops taking tasks and the runs the sink lost count as not done. Its own header so that the
// journal writer's error can be one without the writer knowing the sinks.

#include <stdexcept>

namespace agv {

// The message names the sink's file and the OS error.
class SinkError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace agv
