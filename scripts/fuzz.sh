#!/usr/bin/env bash
# Builds the libFuzzer harnesses (tests/fuzz: .map reader, .scen reader, config loader) with
# clang, ASan and UBSan in build-fuzz/ (or in FUZZ_BUILD_DIR: CI reuses scripts/sanitize.sh's
# build-asan/, which holds them), then fuzzes each for SECONDS (default 30) of a core's time (all
# at once, for SECONDS x harnesses / cores of wall time when they outnumber the cores), from the
# seed corpus in tests/fuzz/corpus/ (never modified: new inputs go to BUILD_DIR/corpus/).
# Prints each harness's executions; exits non-zero on any finding (crash, sanitizer report,
# leak, uncaught exception, input slower than 5 s, memory over the limit), whose reproducer is
# left in BUILD_DIR/findings/. The project's library packages come from scripts/setup.sh.
#
# Usage: scripts/fuzz.sh [SECONDS]      e.g. scripts/fuzz.sh 3600 for a long run
# Env:   FUZZ_TARGETS="fuzz_map fuzz_scen fuzz_config" (a subset), FUZZ_RSS_MB=2048,
#        FUZZ_BUILD_DIR=build-fuzz (a tree configured with -DAGVBENCH_FUZZ=ON is used as it is)
# Replay one input: BUILD_DIR/tests/fuzz/fuzz_map FILE
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-30}
targets=(${FUZZ_TARGETS:-fuzz_map fuzz_scen fuzz_config})
rss_mb=${FUZZ_RSS_MB:-2048}
dir=${FUZZ_BUILD_DIR:-build-fuzz}

scripts/apt_need.sh clang libclang-rt-14-dev cmake ninja-build
jobs=$(nproc 2>/dev/null || echo 2)
# -O1 -g1, as the sanitizer builds (scripts/sanitize.sh): line tables for the reports' stacks,
# and a build that is not the longest part of a 30-second fuzz run.
if ! grep -qs '^AGVBENCH_FUZZ:BOOL=ON$' "$dir/CMakeCache.txt"; then
  cmake -S . -B "$dir" -G Ninja -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DAGVBENCH_FUZZ=ON -DAGVBENCH_BUILD_PERF=OFF \
    >/dev/null
fi
cmake --build "$dir" -j "$jobs" --target "${targets[@]}"

mkdir -p "$dir/findings"
# Every harness at once, for as long as gives each SECONDS of a core: three harnesses on two cores
# run 45 s for 30, and no core idles while the last one runs alone.
n=${#targets[@]}
wall=$(( n > jobs ? (seconds * n + jobs - 1) / jobs : seconds ))
fuzz_one() {  # TARGET: fuzzes it, then writes its summary line and exit code to $dir/TARGET.result
  local t=$1 kind=${1#fuzz_} rc=0
  local work=$dir/corpus/$kind log=$dir/$1.log
  mkdir -p "$work"
  "$dir/tests/fuzz/$t" "$work" "tests/fuzz/corpus/$kind" \
    -max_total_time="$wall" -timeout=5 -rss_limit_mb="$rss_mb" -print_final_stats=1 \
    -artifact_prefix="$dir/findings/$t-" >"$log" 2>&1 || rc=$?
  local execs cov
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  cov=$(grep -E '^#[0-9]+[[:space:]]+DONE' "$log" | tail -1 | grep -oE 'cov: [0-9]+ ft: [0-9]+' || true)
  echo "$rc $t: ${execs:-?} executions in ${wall}s on $jobs cores shared by $n, ${cov:-cov: ?}, corpus $(ls "$work" | wc -l) inputs, exit $rc" \
    >"$dir/$t.result"
}
for t in "${targets[@]}"; do
  echo "fuzz: $t for ${wall}s of wall time (${seconds}s of a core)"
  fuzz_one "$t" &
done
wait
status=0
summary=()
for t in "${targets[@]}"; do
  read -r rc line <"$dir/$t.result"
  summary+=("$line")
  if ((rc != 0)); then
    status=1
    echo "fuzz: $t FAILED (exit $rc); log $dir/$t.log; reproducer:" >&2
    ls -1 "$dir/findings/$t"-* >&2 2>/dev/null || true
    grep -E 'ERROR|SUMMARY|==[0-9]+==|runtime error|fuzz_[a-z]+:' "$dir/$t.log" | head -20 >&2 || true
  fi
done
printf 'fuzz: %s\n' "${summary[@]}"
exit $status
