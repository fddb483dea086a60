#!/usr/bin/env bash
# Bad input (DEVELOPERS.md non-negotiable 5): each case must print a clear message naming the
# field or line, exit with code 2, and leave no report file behind.
# Usage: test_bad_input.sh AGVBENCH_BINARY
set -u
bin=$1
source "$(dirname "$0")/lib.sh"

good_config() {  # a small valid config; $1 = report path
  cat <<JSON
{"name": "t", "seed": 1, "sizes": [16], "densities": [0.1], "maps_per_cell": 2,
 "planners": ["astar"], "report": "$1"}
JSON
}

# expect NAME PATTERN COMMAND...: exit code 2, stderr matching PATTERN, no report.json
expect() {
  local name=$1 pattern=$2
  shift 2
  rm -f report.json
  "$@" >out.txt 2>err.txt
  local code=$?
  if [ $code -ne 2 ]; then
    echo "FAIL $name: exit $code, expected 2"; cat err.txt; fail=$((fail + 1)); return
  fi
  if ! grep -qE -- "$pattern" err.txt; then
    echo "FAIL $name: message does not match /$pattern/:"; cat err.txt; fail=$((fail + 1)); return
  fi
  if [ -e report.json ] || ls report.json.tmp* >/dev/null 2>&1; then
    echo "FAIL $name: a report file was written"; fail=$((fail + 1)); return
  fi
  echo "ok   $name: $(head -c 200 err.txt)"
  pass=$((pass + 1))
}

printf '{"name": "t", "sizes": [16],\n "planners": ["astar" \n' >malformed.json
expect "malformed JSON" 'malformed.json:3' "$bin" run malformed.json --out report.json

good_config report.json | sed 's/"astar"/"warp_drive"/' >unknown_planner.json
expect "unknown planner" 'unknown planner "warp_drive"' "$bin" run unknown_planner.json

good_config report.json | sed 's/"astar"/{"name": "astar", "params": {"bogus": 1}}/' >unknown_param.json
expect "unknown parameter" 'params.bogus: unknown parameter' "$bin" run unknown_param.json

good_config report.json | sed 's/"astar"/{"name": "astar", "params": {"diagonal_cost": 7}}/' >range_param.json
expect "parameter out of range" 'diagonal_cost: 7 is outside' "$bin" run range_param.json

good_config report.json | sed 's/0.1\]/1.5]/' >density.json
expect "density out of range" 'densities\[0\]: 1.5 is outside' "$bin" run density.json

good_config report.json | sed 's/"maps_per_cell": 2/"maps_per_cell": -3/' >maps.json
expect "maps_per_cell out of range" 'maps_per_cell: -3 is outside' "$bin" run maps.json

good_config report.json | sed 's/"seed": 1/"seed": 1, "sede": 2/' >typo.json
expect "unknown field" 'sede: unknown field' "$bin" run typo.json

good_config report.json | sed 's/"sizes"/"generators": ["uniform", {"name": "rooms", "params": {"room_size": 1}}], "sizes"/' >room_size.json
expect "shape parameter out of range" 'generators\[1\]\.params\.room_size: 1 is outside \[2, 8192\]' "$bin" run room_size.json

good_config report.json | sed 's/"sizes"/"generators": [{"name": "maze", "params": {"walls": 2}}], "sizes"/' >shape_unknown.json
expect "unknown shape parameter" 'generators\[0\]\.params\.walls: unknown parameter' "$bin" validate shape_unknown.json

good_config report.json | sed 's/"sizes"/"generators": ["rooms"], "map": {"room_size": 6}, "sizes"/' >shape_in_map.json
expect "shape parameter in map (old config)" 'map\.room_size: a shape parameter of generator "rooms"; it now goes in' "$bin" run shape_in_map.json

# Odd files (issue 15): only regular files are read, and the message names the file.
mkdir -p config_dir
expect "config is a directory" 'config file "config_dir": a directory, not a regular file' \
  "$bin" run config_dir --out report.json
expect "config is a device" 'config file "/dev/zero": a character device' "$bin" validate /dev/zero
rm -f fifo.map && mkfifo fifo.map
expect "map is a FIFO" 'map file "fifo.map": a FIFO, not a regular file' \
  timeout 20 "$bin" plan --map fifo.map --start 0,0 --goal 1,1
expect "missing config file" 'config file "nope.json": No such file' "$bin" run nope.json --out report.json
good_config report.json >good.json
expect "resume into another journal" '--resume: the journal is appended to' \
  "$bin" run good.json --resume j.jsonl --runs-out other.jsonl
expect "validate: unknown planner" 'unknown planner' "$bin" validate unknown_planner.json

printf 'type octile\nheight 3\nwidth 3\nmap\n...\n.x.\n...\n' >badchar.map
expect "map: bad character" 'badchar.map:6' "$bin" plan --map badchar.map --start 0,0 --goal 2,2
printf 'type octile\nheight 4\nwidth 3\nmap\n...\n...\n' >short.map
expect "map: too few rows" 'short.map' "$bin" plan --map short.map --start 0,0 --goal 2,2
expect "map: unreadable" 'missing.map' "$bin" plan --map missing.map --start 0,0 --goal 1,1
printf 'type octile\nheight 3\nwidth 3\nmap\n...\n.@.\n...\n' >ok.map
expect "start outside the grid" '--start: \(5,0\) is outside' "$bin" plan --map ok.map --start 5,0 --goal 2,2
expect "goal on an obstacle" '--goal: \(1,1\) is an obstacle' "$bin" plan --map ok.map --start 0,0 --goal 1,1
expect "fixed endpoint outside" '--start: \[25, 14\] is outside the 21x21 grid' "$bin" plan --size 21 --endpoints fixed --start 25,14 --goal 1,1
expect "fixed endpoints, no goal" '--endpoints fixed: --start and --goal are required' "$bin" plan --size 21 --endpoints fixed --start 5,14
expect "unknown CLI planner" 'unknown planner "nope"' "$bin" plan --planner nope
expect "unknown CLI parameter" '--param frobnicate' "$bin" plan --param frobnicate=3
expect "unknown CLI generator" 'unknown generator "spiral"' "$bin" plan --generator spiral
expect "unknown CLI generator parameter" '--gen-param corridor: generator rooms has no such parameter' \
  "$bin" plan --generator rooms --gen-param corridor=2
expect "CLI generator parameter out of range" '--gen-param.corridor: 40 is outside \[1, 32\]' \
  "$bin" plan --generator maze --size 32 --gen-param corridor=40
printf 'version 1\n0\tok.map\t3\t3\t0\t0\t1\t1\t1.41421356\n' >obstacle.scen
expect "scen: goal on an obstacle" 'query 1: goal \(1,1\) is an obstacle' "$bin" scen ok.map obstacle.scen
printf 'version 1\n0\tok.map\t3\t3\t0\t0\tx\t1\t1.4\n' >garbled.scen
expect "scen: malformed line" 'garbled.scen:2' "$bin" scen ok.map garbled.scen
printf 'version 1\n0\tother.map\t3\t3\t0\t0\t1\t0\t1\n' >other.scen
expect "scen: queries of another map" "query 1: names map 'other.map', not ok.map" "$bin" scen ok.map other.scen
printf 'version 1\n0\tok.map\t3\t3\t0\t0\t2\t2\t1.5\n' >short.scen
expect "scen: optimum shorter than the straight line" 'short.scen:2: optimal length 1.5 is shorter than the straight line' "$bin" scen ok.map short.scen
expect "CLI: bad option value" 'threads' "$bin" run --threads -4

# The config as a whole (issue 15, classes 5 and 6): `validate` refuses everything `run` would,
# before run opens any file.
both() {  # both NAME PATTERN CONFIG: validate and run each refuse CONFIG
  expect "validate: $1" "$2" "$bin" validate "$3"
  expect "run: $1" "$2" "$bin" run "$3" --out report.json
}
good_config report.json | sed 's/"sizes": \[16\]/"sizes": [64, 16], "map": {"endpoints": "random", "min_distance": 30}/' >min_distance.json
both "map option impossible at one size" 'min_distance.json: map\.min_distance: 30 is outside \[0, 21\.2132\].*sizes\[1\] \(16x16\)' min_distance.json
good_config report.json | sed 's/"sizes": \[16\]/"sizes": [64, 16], "generators": [{"name": "maze", "params": {"corridor": 40}}]/' >corridor.json
both "shape parameter impossible at one size" 'generators\[0\]\.params\.corridor: 40 is outside \[1, 16\]' corridor.json
printf 'j1\nj2\n' >kept.jsonl
expect "run: a refused config leaves an existing journal as it was" 'min_distance' \
  "$bin" run min_distance.json --out report.json --runs-out kept.jsonl
[ "$(cat kept.jsonl)" = "$(printf 'j1\nj2')" ] && ok "journal untouched" || bad "journal changed"
good_config report.json | sed 's/"seed": 1,/"seed": 1,\n "seed": 2,/' >dup_key.json
both "duplicate key" 'dup_key.json:2:2: key "seed" appears twice' dup_key.json
good_config report.json | sed 's/"sizes": \[16\]/"sizes": [16, [16, 16]]/' >dup_size.json
both "size given twice" 'sizes\[1\]: 16x16 is also sizes\[0\]' dup_size.json
good_config report.json | sed 's/"densities": \[0.1\]/"densities": [0.1, 0.10000000001]/' >dup_density.json
both "densities with one cell key" 'densities\[1\]: 0.10000000001 names the same cells as densities\[0\]' dup_density.json
good_config report.json | sed 's/"sizes": \[16\]/"generators": ["uniform", "uniform"], "sizes": [16]/' >dup_generator.json
both "generator listed twice" 'generators\[1\]: generator "uniform" appears twice' dup_generator.json
sizes=$(seq -s, 2 1001)
good_config report.json | sed "s/\"sizes\": \[16\]/\"sizes\": [$sizes]/; s/\"maps_per_cell\": 2/\"maps_per_cell\": 10000000/" >huge.json
both "sweep too large for memory (was std::bad_alloc)" 'maps_per_cell: 10000000 maps in each of 1000 cells.*lower maps_per_cell' huge.json

finish test_bad_input
