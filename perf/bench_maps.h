#pragma once
// Map set-up shared by the microbenchmarks, so that a case name such as "uniform64_d0.2" means
// the same generator settings in every table of perf/README.md. Each benchmark keeps its own
// seeds (their maps are the ones its recorded figures were measured on).

#include <cstdio>
#include <string>

#include "generators/map_generators.h"

namespace agv {

// Uniform random obstacles, endpoints in opposite corners, solvable under `solvable_rule`.
inline MapSpec bench_uniform_spec(int side, double density, CornerRule solvable_rule) {
  MapSpec spec;
  spec.generator = "uniform";
  spec.width = side;
  spec.height = side;
  spec.density = density;
  spec.endpoints = EndpointMode::corners;
  spec.require_solvable = true;
  spec.solvable_rule = solvable_rule;
  return spec;
}

inline std::string bench_uniform_name(int side, double density) {
  char name[64];
  std::snprintf(name, sizeof name, "uniform%d_d%.1f", side, density);
  return name;
}

}  // namespace agv
