# Shared by the CLI test scripts (sourced): a scratch folder to work in, removed on exit, and
# pass/fail bookkeeping. `check NAME COMMAND...` passes when the command exits 0 (its output in
# out.txt and err.txt); `finish NAME` prints the tally and returns non-zero on any failure.
# `movingai_sets SOURCE_DIR` prints the MovingAI sets' folder by tests/movingai_data.h's rule
# ($AGVBENCH_MOVINGAI_DIR, else ../shared/maps beside the checkout); returns 1 when there is
# none, 2 when AGVBENCH_MOVINGAI_DIR names no folder (a mistyped folder is an error, not a skip).
# `$py "$journal_check" J [N]` checks a journal holds each run once (N of them); a journal's run
# records are its lines with a "planner" key (`grep -c '"planner":'`), besides its header and
# per-map records.
# `"${isolate[@]}"` is --isolate as a sanitized build can run it: sanitizers reserve terabytes of
# address space for their shadow memory, more than the workers' default cap (RLIMIT_AS) allows,
# so a sanitized build's ctest sets AGV_ISOLATE_MEMORY_MB (tests/CMakeLists.txt).
py=/usr/bin/python3
# A journal's runs decoded, counted and checked for repeats (either journal version).
journal_check=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/journal_check.py
export AGV_JOURNAL_CHECK=$journal_check  # for the scripts' Python snippets
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
pass=0
fail=0
ok() { echo "ok   $1"; pass=$((pass + 1)); }
bad() { echo "FAIL $1"; fail=$((fail + 1)); }
isolate=(--isolate ${AGV_ISOLATE_MEMORY_MB:+--isolate-memory "$AGV_ISOLATE_MEMORY_MB"})
check() {  # NAME COMMAND...
  local name=$1
  shift
  if "$@" >out.txt 2>err.txt; then
    ok "$name"
  else
    bad "$name (exit $?)"
    cat out.txt err.txt | tail -20
  fi
}
movingai_sets() {  # SOURCE_DIR
  if [ -n "${AGVBENCH_MOVINGAI_DIR:-}" ]; then
    [ -d "$AGVBENCH_MOVINGAI_DIR" ] || {
      echo "AGVBENCH_MOVINGAI_DIR=$AGVBENCH_MOVINGAI_DIR is not a folder" >&2
      return 2
    }
    echo "$AGVBENCH_MOVINGAI_DIR"
  elif [ -d "$1/../shared/maps" ]; then
    (cd "$1/../shared/maps" && pwd)
  else
    return 1
  fi
}
finish() {
  echo "$1: $pass passed, $fail failed"
  [ "$fail" -eq 0 ]
}
