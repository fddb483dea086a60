#include "engine/system/phase_clock.h"

#include <atomic>

#include "algos/planner.h"

namespace agv {

namespace {

std::atomic<bool> g_enabled{false};
std::array<std::atomic<std::int64_t>, static_cast<int>(EnginePhase::count)> g_totals{};

}  // namespace

void enable_phase_clock(bool on) { g_enabled.store(on, std::memory_order_relaxed); }

bool phase_clock_enabled() { return g_enabled.load(std::memory_order_relaxed); }

PhaseTotals phase_clock_totals() {
  PhaseTotals out{};
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = g_totals[i].load(std::memory_order_relaxed);
  return out;
}

void reset_phase_clock() {
  for (auto& t : g_totals) t.store(0, std::memory_order_relaxed);
}

void add_phase_time(EnginePhase phase, std::int64_t ns) {
  if (phase_clock_enabled())
    g_totals[static_cast<std::size_t>(phase)].fetch_add(ns, std::memory_order_relaxed);
}

PhaseScope::PhaseScope(EnginePhase phase) : phase_(phase) {
  if (phase_clock_enabled()) start_ = thread_cpu_ns();
}

PhaseScope::~PhaseScope() {
  if (start_ >= 0) add_phase_time(phase_, thread_cpu_ns() - start_);
}

}  // namespace agv
