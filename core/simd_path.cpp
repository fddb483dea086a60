#include "core/simd_path.h"

#include <cstdlib>
#include <string>

#include "core/input_error.h"
#include "core/printable.h"

namespace agv {
namespace {

// Whether this build compiled the level (cmake/agv_simd_levels.cmake defines AGV_SIMD_LEVELS_X86
// when it compiles the x86-64 levels).
bool built(SimdPath path) {
#if AGV_SIMD_LEVELS_X86
  (void)path;
  return true;
#else
  return path == SimdPath::baseline;
#endif
}

// Whether the CPU and OS run the level: every feature its target list enables
// (cmake/agv_simd_levels.cmake). __builtin_cpu_supports checks the OS saves the vector registers
// too.
bool cpu_runs(SimdPath path) {
#if AGV_SIMD_LEVELS_X86
  __builtin_cpu_init();
  const bool avx2 = __builtin_cpu_supports("sse3") && __builtin_cpu_supports("ssse3") &&
                    __builtin_cpu_supports("sse4.1") && __builtin_cpu_supports("sse4.2") &&
                    __builtin_cpu_supports("popcnt") && __builtin_cpu_supports("avx") &&
                    __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") &&
                    __builtin_cpu_supports("bmi") && __builtin_cpu_supports("bmi2");
  const bool avx512 = avx2 && __builtin_cpu_supports("avx512f") &&
                      __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512cd") &&
                      __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512vl");
  switch (path) {
    case SimdPath::baseline:
      return true;
    case SimdPath::avx2:
      return avx2;
    case SimdPath::avx512:
      return avx512;
  }
#endif
  return path == SimdPath::baseline;
}

SimdPath best_supported() {
  SimdPath best = SimdPath::baseline;
  for (SimdPath path : kSimdPaths)
    if (simd_path_supported(path)) best = path;
  return best;
}

SimdPath chosen_path() {
  const char* env = std::getenv("AGVBENCH_SIMD");
  if (env == nullptr || *env == '\0' || std::string_view(env) == "auto") return best_supported();
  const std::string shown = "AGVBENCH_SIMD=" + printable(env, 40);
  for (SimdPath path : kSimdPaths) {
    if (simd_path_name(path) != env) continue;
    if (!built(path))
      throw InputError(shown + ": this build has no " + std::string(env) +
                       " level (only x86-64 builds do)");
    if (!cpu_runs(path))
      throw InputError(shown + ": this CPU cannot run the " + std::string(env) +
                       " level; it runs " + std::string(simd_path_name(best_supported())));
    return path;
  }
  throw InputError(shown + " is not one of baseline, avx2, avx512, auto");
}

}  // namespace

std::string_view simd_path_name(SimdPath path) {
  switch (path) {
    case SimdPath::baseline:
      return "baseline";
    case SimdPath::avx2:
      return "avx2";
    case SimdPath::avx512:
      return "avx512";
  }
  return "unknown";
}

bool simd_path_supported(SimdPath path) { return built(path) && cpu_runs(path); }

SimdPath active_simd_path() {
  static const SimdPath path = chosen_path();
  return path;
}

}  // namespace agv
