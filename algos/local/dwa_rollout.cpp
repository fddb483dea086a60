#include "algos/local/dwa_rollout.h"

namespace agv {

// One table per compiled level (algos/local/dwa_rollout_kernel.cpp, algos/CMakeLists.txt).
namespace dwa_levels {
namespace baseline {
extern const DwaRolloutKernel kKernel;
}
#if AGV_SIMD_LEVELS_X86
namespace avx2 {
extern const DwaRolloutKernel kKernel;
}
namespace avx512 {
extern const DwaRolloutKernel kKernel;
}
#endif
}  // namespace dwa_levels

const DwaRolloutKernel* dwa_rollout_kernel(SimdPath path) {
#if AGV_SIMD_LEVELS_X86
  return level_kernel(path, &dwa_levels::baseline::kKernel, &dwa_levels::avx2::kKernel,
                      &dwa_levels::avx512::kKernel);
#else
  return level_kernel<DwaRolloutKernel>(path, &dwa_levels::baseline::kKernel, nullptr, nullptr);
#endif
}

const DwaRolloutKernel& active_dwa_rollout_kernel() {
  static const DwaRolloutKernel& kernel = *dwa_rollout_kernel(active_simd_path());
  return kernel;
}

}  // namespace agv
