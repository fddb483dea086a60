#pragma once
// Compiling one source once per instruction-set level (core/simd_path.h;
// cmake/agv_simd_levels.cmake compiles each level's copy with AGV_SIMD_LEVEL, the namespace of the
// copy, and, but for the baseline, AGV_SIMD_TARGET, its target-feature list). In a level source,
// after every #include:
//
//   AGV_SIMD_TARGET_BEGIN
//   namespace agv::foo_levels::AGV_SIMD_LEVEL { ... }
//   AGV_SIMD_TARGET_END
//
// The features apply to the functions defined between the two, never to the headers' inline
// functions: a copy of one that the compiler keeps out of line is compiled for the build's own
// target, so the linker cannot hand a level's instructions to callers on a CPU without them
// (ctest layout_simd_levels checks each such copy in a level object is the baseline object's).

#if defined(AGV_SIMD_TARGET)
#define AGV_SIMD_STR(x) #x
#define AGV_SIMD_PRAGMA(x) _Pragma(AGV_SIMD_STR(x))
#if defined(__clang__)
#define AGV_SIMD_TARGET_BEGIN \
  AGV_SIMD_PRAGMA(            \
      clang attribute push(__attribute__((target(AGV_SIMD_TARGET))), apply_to = function))
#define AGV_SIMD_TARGET_END AGV_SIMD_PRAGMA(clang attribute pop)
#else
#define AGV_SIMD_TARGET_BEGIN \
  AGV_SIMD_PRAGMA(GCC push_options) AGV_SIMD_PRAGMA(GCC target(AGV_SIMD_TARGET))
#define AGV_SIMD_TARGET_END AGV_SIMD_PRAGMA(GCC pop_options)
#endif
#else
#define AGV_SIMD_TARGET_BEGIN
#define AGV_SIMD_TARGET_END
#endif
