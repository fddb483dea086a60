#pragma once
// How many random maps (or runs) a property test draws. Under a sanitizer (AGV_SANITIZED_BUILD,
// tests/CMakeLists.txt: the ASan+UBSan and TSan trees) a test runs 5 to 20 times slower, and what
// the sanitizer adds is a check of the code's memory, undefined behaviour and threads, which a few
// maps exercise as well as many: there those tests draw `sanitized`; the plain suite draws
// `plain`, the count that proves the property itself.

namespace agv::test {

#ifdef AGV_SANITIZED_BUILD
inline constexpr bool kSanitized = true;
#else
inline constexpr bool kSanitized = false;
#endif

constexpr int sized(int plain, int sanitized) { return kSanitized ? sanitized : plain; }

}  // namespace agv::test
