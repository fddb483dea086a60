#pragma once
// Map set-up shared by the microbenchmarks, so that a case name such as "uniform64_d0.2" means
// the same generator settings in every table of perf/README.md. Each benchmark keeps its own
// seeds (their maps are the ones its recorded figures were measured on).

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

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

// "uniform64_d0.2", "blocks64_d0.3"
inline std::string bench_case_name(const std::string& generator, int side, double density) {
  char name[64];
  std::snprintf(name, sizeof name, "%s%d_d%.1f", generator.c_str(), side, density);
  return name;
}
inline std::string bench_uniform_name(int side, double density) {
  return bench_case_name("uniform", side, density);
}

// A benchmark case: its maps and the name its table rows carry.
struct BenchCase {
  std::string name;
  std::vector<MapInstance> maps;
};

// `count` maps of `generator` (its default shape parameters) at this side and density, corner to
// corner and solvable under no_corner_cut (the papers' protocol); map i drawn from
// Rng(seed, density * 10 * 1000 + i).
inline BenchCase bench_case(const std::string& generator, int side, double density, int count,
                            std::uint64_t seed) {
  MapSpec spec = bench_uniform_spec(side, density, CornerRule::no_corner_cut);
  spec.generator = generator;
  BenchCase c{bench_case_name(generator, side, density), {}};
  for (int i = 0; i < count; ++i) {
    Rng rng(seed, static_cast<std::uint64_t>(density * 10) * 1000 + static_cast<std::uint64_t>(i));
    c.maps.push_back(make_map(spec, rng));
  }
  return c;
}

}  // namespace agv
