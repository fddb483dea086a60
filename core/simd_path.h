#pragma once
// Which instruction-set level the line-of-sight kernel runs at (perf/README.md "Line of sight",
// "Portable builds"). The kernel is compiled once per level (core/line_of_sight_kernel.cpp); the
// process runs the best level its CPU supports, so one portable build (AGVBENCH_NATIVE=OFF) serves
// a cluster of mixed nodes or an installed module at the speed of a build for each machine.
//
//   baseline  the build's own target: x86-64 (SSE2) in a portable build, the build machine's
//             CPU in a native one (-march=native), or whatever a non-x86 build targets;
//   avx2      x86-64-v3's vector and bit instructions (AVX2, FMA, BMI1/2, POPCNT, SSE4.2);
//   avx512    avx2 with AVX-512 F, BW, CD, DQ and VL (x86-64-v4).
//
// Every level gives the same verdicts bit for bit (tests/core/test_los_simd.cpp runs each level
// the CPU supports). The environment variable AGVBENCH_SIMD=baseline|avx2|avx512 forces a level,
// to measure or test one; AGVBENCH_SIMD=auto or unset picks the best.

#include <string_view>

namespace agv {

enum class SimdPath { baseline, avx2, avx512 };
inline constexpr SimdPath kSimdPaths[] = {SimdPath::baseline, SimdPath::avx2, SimdPath::avx512};

std::string_view simd_path_name(SimdPath path);

// Whether this build has `path` (avx2 and avx512 only on x86-64) and the CPU and OS run it.
bool simd_path_supported(SimdPath path);

// The level the process runs, chosen once: $AGVBENCH_SIMD, else the best supported. Throws
// InputError naming AGVBENCH_SIMD when it is not one of the names above or names a level this
// CPU or build lacks (the CLI checks it before a command runs; a library user may call this at
// start-up to do the same, or meet the error at the first line-of-sight check).
SimdPath active_simd_path();

// A kernel's copy for `path` among its per-level copies (nullptr for a level the build did not
// compile), or nullptr when the build or the CPU lacks the level.
template <class Kernel>
const Kernel* level_kernel(SimdPath path, const Kernel* baseline, const Kernel* avx2,
                           const Kernel* avx512) {
  if (!simd_path_supported(path)) return nullptr;
  const Kernel* const by_level[] = {baseline, avx2, avx512};
  return by_level[static_cast<int>(path)];
}

}  // namespace agv
