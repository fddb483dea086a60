#pragma once
// The per-run random stream. Every stochastic planner and generator draws only from the Rng
// handed to it, seeded from (sweep seed, map index, planner name), so a run is reproducible from
// its record alone, on any thread count. Numbers are mapped from raw 32-bit draws by our own
// code: the standard distributions differ between standard libraries.

#include <cstdint>
#include <pcg_random.hpp>
#include <string_view>

namespace agv {

// FNV-1a, 64-bit: a stable hash of names (planner names, generator names) across platforms.
constexpr std::uint64_t stable_hash(std::string_view text) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (char c : text) {
    h ^= static_cast<unsigned char>(c);
    h *= 0x100000001b3ULL;
  }
  return h;
}

// SplitMix64 finaliser: decorrelates nearby seeds (map 0, 1, 2, ...).
constexpr std::uint64_t mix64(std::uint64_t z) {
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

class Rng {
 public:
  // An independent pcg32 stream per (seed, stream); the stream id selects one of 2^63 streams.
  Rng(std::uint64_t seed, std::uint64_t stream) : engine_(mix64(seed), stream) {}

  // The stream of one run: (sweep seed, map index, purpose) -> (state, stream).
  static Rng for_run(std::uint64_t sweep_seed, std::uint64_t map_index, std::string_view purpose) {
    return Rng(mix64(sweep_seed ^ mix64(map_index)), stable_hash(purpose));
  }

  std::uint32_t next_u32() { return engine_(); }

  // Uniform in [0, 1) with 53 random bits.
  double uniform01() {
    const std::uint64_t hi = next_u32() >> 5;  // 27 bits
    const std::uint64_t lo = next_u32() >> 6;  // 26 bits
    return static_cast<double>((hi << 26) | lo) * 0x1.0p-53;
  }
  // Uniform in [lo, hi).
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform01(); }

  // Uniform integer in [0, n), n >= 1, unbiased (Lemire's multiply-and-reject).
  std::uint32_t below(std::uint32_t n) {
    std::uint64_t m = static_cast<std::uint64_t>(next_u32()) * n;
    auto low = static_cast<std::uint32_t>(m);
    if (low < n) {
      const std::uint32_t threshold = static_cast<std::uint32_t>(-n) % n;
      while (low < threshold) {
        m = static_cast<std::uint64_t>(next_u32()) * n;
        low = static_cast<std::uint32_t>(m);
      }
    }
    return static_cast<std::uint32_t>(m >> 32);
  }
  // Uniform integer in [lo, hi], inclusive.
  int between(int lo, int hi) {
    return lo + static_cast<int>(below(static_cast<std::uint32_t>(hi - lo) + 1U));
  }
  bool chance(double p) { return uniform01() < p; }

 private:
  pcg32 engine_;
};

}  // namespace agv
