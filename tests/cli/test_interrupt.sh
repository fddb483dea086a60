#!/usr/bin/env bash
# Ctrl-C under --isolate (issue 15, class 3), as a terminal sends it: SIGINT to the sweep's whole
# process group. The isolated workers have process groups of their own, so the runs in flight
# finish and are recorded, no run is recorded as a crash, and --resume completes the sweep to
# the uninterrupted report (non-timing fields), every run exactly once. A second signal, or
# SIGTERM, cuts the runs in flight short: the sweep ends at once, those runs are not recorded
# and no worker is left behind. Usage: test_interrupt.sh AGVBENCH SOURCE_DIR
set -u
bin=$1
src=$2
same=$src/slurm/same_report.py
source "$(dirname "$0")/lib.sh"

# 1,200 runs: the signal lands at 30% of them with room to spare. A sanitized build (AGV_SANITIZED,
# tests/CMakeLists.txt) runs each map ten times slower or more: 20 maps per cell still give the
# signal time to land mid-sweep, at two fifths of the cost.
maps=50
[ "${AGV_SANITIZED:-0}" = 1 ] && maps=20
cat >config.json <<JSON
{"name": "interrupt-test", "seed": 5, "generators": ["uniform", "rooms"], "sizes": [96, 128],
 "densities": [0.1, 0.3], "maps_per_cell": $maps, "planners": ["astar", "dijkstra", "bidir_astar"],
 "report": "unused.json"}
JSON
total=$((2 * 2 * 2 * maps * 3))

# Every record once; no record says the run crashed or hit the hard limit.
cat >journal_ok.py <<EOF_PY
import collections, json, subprocess, sys
out = subprocess.run(["$py", "$journal_check", "--dump", sys.argv[1]], check=True, capture_output=True, text=True).stdout
records = [json.loads(l) for l in out.splitlines()]
ids = collections.Counter((r["cell"], r["map_index"], r["planner"]) for r in records)
lost = [r["outcome"] for r in records if r["outcome"] in ("crash", "timeout", "oom")]
print(f"{len(records)} records, {sum(ids.values()) - len(ids)} repeated, lost: {lost[:5]}")
sys.exit(0 if not lost and len(ids) == len(records) and len(records) >= int(sys.argv[2]) else 1)
EOF_PY
incomplete() {
  $py -c "import json,sys; r=json.load(open('$1')); sys.exit(0 if r['complete'] is False else 1)"
}
# The run records of a journal (not its header or map records).
lines() { if [ -e "$1" ]; then grep -c '"planner":' "$1"; else echo 0; fi; }

# Starts `agvbench run ARGS` as a terminal's foreground job: a session and process group of its
# own (setsid), whose id is written to pgid.txt; `$!` waits for it.
start_group() {
  rm -f pgid.txt
  setsid bash -c 'echo $$ >pgid.txt; exec "$0" "$@"' "$bin" run "$@" &
  for _ in $(seq 1 200); do [ -s pgid.txt ] && break; sleep 0.01; done
  pgid=$(cat pgid.txt)
}
# Processes left in the sweep's session (its workers, had they survived it).
left_in_session() { ps -eo sid=,pid= | awk -v s="$1" '$1 == s' | wc -l; }

"$bin" run config.json --threads 2 --out full.json --quiet || { bad "uninterrupted run"; exit 1; }

# 1. One Ctrl-C at about 30% of an isolated sweep: runs in flight finish and are recorded.
rm -f j.jsonl part.json final.json
start_group config.json "${isolate[@]}" --threads 2 --out part.json --runs-out j.jsonl --quiet
pid=$!
for _ in $(seq 1 3000); do
  [ "$(lines j.jsonl)" -ge $((total * 30 / 100)) ] && break
  kill -0 $pid 2>/dev/null || break
  sleep 0.01
done
kill -INT -- "-$pgid" 2>/dev/null
wait $pid
code=$?
if [ $code -eq 130 ]; then
  incomplete part.json && ok "SIGINT to the group at $(lines j.jsonl)/$total runs: exit 130, incomplete report" \
    || bad "SIGINT to the group: report not marked incomplete"
else
  bad "SIGINT to the group: exit $code (expected 130)"
fi
$py journal_ok.py j.jsonl 1 && ok "SIGINT to the group: no run recorded as crash or timeout" \
  || bad "SIGINT to the group: the journal records runs the interruption cut"
[ "$(left_in_session "$pgid")" -eq 0 ] && ok "SIGINT to the group: no worker left" \
  || bad "SIGINT to the group: $(left_in_session "$pgid") processes left in the session"
"$bin" run config.json "${isolate[@]}" --threads 2 --out final.json --resume j.jsonl --quiet
[ $? -eq 0 ] || bad "resume after SIGINT: non-zero exit"
$py "$same" full.json final.json && ok "resume after SIGINT: report equals the uninterrupted one" \
  || bad "resume after SIGINT: report differs"
$py journal_ok.py j.jsonl $total && ok "resume after SIGINT: every run exactly once, none lost" \
  || bad "resume after SIGINT: runs missing, repeated or lost"

# 2. Runs that would take two minutes each (an ant colony of many iterations, a time limit of
# 120 s): a second Ctrl-C, or one SIGTERM, cuts them short at once; none is recorded.
cat >long.json <<'JSON'
{"name": "long-runs", "seed": 2, "sizes": [64], "densities": [0.2], "maps_per_cell": 4,
 "time_limit_s": 120,
 "planners": [{"name": "aco", "params": {"ants": 1000, "iterations": 10000000}}],
 "report": "unused.json"}
JSON
for how in "INT INT" "TERM"; do
  rm -f lj.jsonl long.out.json
  start_group long.json "${isolate[@]}" --threads 2 --out long.out.json --runs-out lj.jsonl --quiet
  pid=$!
  # Until both workers are up (the sweep and its two workers in the session): their first
  # runs, two minutes each, are then in flight.
  for _ in $(seq 1 200); do [ "$(left_in_session "$pgid")" -ge 3 ] && break; sleep 0.05; done
  t0=$(date +%s)
  for sig in $how; do
    kill "-$sig" -- "-$pgid" 2>/dev/null
    sleep 0.5
  done
  # Bounded wait: the runs in flight would take 120 s.
  for _ in $(seq 1 300); do kill -0 $pid 2>/dev/null || break; sleep 0.1; done
  if kill -0 $pid 2>/dev/null; then
    bad "SIG${how// /, SIG}: the sweep still waits for its runs after 30 s"
    kill -KILL -- "-$pgid" 2>/dev/null
    wait $pid
    continue
  fi
  wait $pid
  code=$?
  [ $code -eq 130 ] && incomplete long.out.json && [ "$(lines lj.jsonl)" -eq 0 ] \
    && ok "SIG${how// /, SIG}: ended in $(($(date +%s) - t0)) s, exit 130, the cut runs not recorded" \
    || bad "SIG${how// /, SIG}: exit $code, $(lines lj.jsonl) records"
  [ "$(left_in_session "$pgid")" -eq 0 ] && ok "SIG${how// /, SIG}: no worker left" \
    || bad "SIG${how// /, SIG}: $(left_in_session "$pgid") processes left in the session"
done

finish test_interrupt
