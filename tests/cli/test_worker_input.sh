#!/usr/bin/env bash
# The hidden `worker` subcommand (the --isolate worker process, engine/sweep/isolated_worker.h) checks
# what it reads (issue 15, class 9): a request naming a map task or a planner the sweep does not
# have, or that is not a request at all, is refused with exit 2 and a message saying which,
# never a crash; a good request still runs. Usage: test_worker_input.sh AGVBENCH
set -u
bin=$1
source "$(dirname "$0")/lib.sh"

# 1 cell x 3 maps = map tasks 0..2; astar (index 0) everywhere, dijkstra (index 1) on map 0 only.
config='{"config": {"name": "w", "seed": 1, "sizes": [16], "densities": [0.1], "maps_per_cell": 3,
 "planners": ["astar", {"name": "dijkstra", "only": {"maps_per_cell": 1}}], "report": "unused.json"}}'
config=$(echo "$config" | tr -d '\n')

# Feeds the config line and REQUEST to a worker; sets code, out and err.
feed() {
  printf '%s\n%s\n' "$config" "$1" | "$bin" worker --memory-mb 0 >out.txt 2>err.txt
  code=$?
  out=$(cat out.txt)
  err=$(head -c 300 err.txt)
}

feed '{"task": 1, "planners": [0]}'
[ $code -eq 0 ] && [ "$(grep -c '"outcome"' out.txt)" -eq 1 ] \
  && ok "a good request runs: exit 0, one record" || bad "good request: exit $code, $out $err"

check_refused() {  # REQUEST WHAT_THE_MESSAGE_NAMES
  feed "$1"
  if [ $code -eq 2 ] && grep -q "$2" err.txt && ! grep -q '"outcome"' out.txt; then
    ok "refused with exit 2: $1 -> $err"
  else
    bad "request $1: exit $code (expected 2 and a message naming $2): $err"
  fi
}
check_refused '{"task": 3, "planners": [0]}' '"task"'
check_refused '{"task": 4294967296, "planners": [0]}' '"task"'
check_refused '{"task": -1, "planners": [0]}' '"task"'
check_refused '{"task": 0.5, "planners": [0]}' '"task"'
check_refused '{"planners": [0]}' '"task"'
check_refused '{"task": 0, "planners": [2]}' 'planner index'
check_refused '{"task": 0, "planners": [-1]}' 'planner index'
check_refused '{"task": 0, "planners": 0}' '"planners"'
check_refused '{"task": 2, "planners": [1]}' 'not scheduled'
check_refused '{"task": 0, "planners": [0], "extra": 1}' 'unknown key'
check_refused 'not json' 'not a JSON object'
check_refused '[1, 2]' 'not a JSON object'

# A config the worker cannot take is answered as such, not a crash.
printf '%s\n' '{"config": {"name": "w", "sizes": [16], "planners": ["nope"]}}' \
  | "$bin" worker --memory-mb 0 >out.txt 2>err.txt
code=$?
[ $code -eq 2 ] && grep -q '"fatal"' out.txt && ok "bad config: exit 2, {\"fatal\": ...}" \
  || bad "bad config: exit $code: $(head -c 200 out.txt)"
: | "$bin" worker --memory-mb 0 >out.txt 2>err.txt
code=$?
[ $code -eq 2 ] && grep -q "no config line" err.txt && ok "no config line: exit 2, named" \
  || bad "no config line: exit $code: $(head -c 200 err.txt)"

finish test_worker_input
