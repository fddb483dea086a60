#!/usr/bin/env bash
# Command-line numbers are read strictly (issue 15, class 8): overflow, nan/inf, a negative where
# none makes sense and trailing text are exit 2 naming the option, never wrapped or accepted;
# the ranges are the config's (a density the config refuses `plan --density` refuses). And
# `--threads` beyond the CPUs runs on the CPUs, saying so, and the report gives what ran.
# Usage: test_strict_cli.sh AGVBENCH_BINARY
set -u
bin=$1
source "$(dirname "$0")/lib.sh"

# refuse NAME PATTERN COMMAND...: exit code 2 and stderr matching PATTERN
refuse() {
  local name=$1 pattern=$2
  shift 2
  "$@" >out.txt 2>err.txt
  local code=$?
  if [ $code -ne 2 ]; then
    bad "$name: exit $code, expected 2"; cat err.txt out.txt | head -5; return
  fi
  if ! grep -qE -- "$pattern" err.txt; then
    bad "$name: message does not match /$pattern/:"; cat err.txt; return
  fi
  ok "$name: $(head -c 160 err.txt)"
}

cat >c.json <<'JSON'
{"name": "t", "sizes": [16], "densities": [0.1], "maps_per_cell": 2, "planners": ["astar"],
 "report": "r.json"}
JSON
printf 'type octile\nheight 3\nwidth 3\nmap\n...\n...\n...\n' >m.map
printf 'version 1\n0\tm.map\t3\t3\t0\t0\t2\t2\t2.82842712\n' >m.scen

refuse "--shard N overflow (was 0/1)" '--shard \(N of i/N\): 4294967297 is outside \[1, 2147483647\]' \
  "$bin" run c.json --shard 0/4294967297 --quiet
refuse "--shard i overflow" '--shard \(i of i/N\): "99999999999999999999" is outside' \
  "$bin" run c.json --shard 99999999999999999999/2 --quiet
refuse "--shard negative N" '--shard \(N of i/N\): -3 is outside' "$bin" run c.json --shard 0/-3
refuse "--shard trailing text" '--shard \(N of i/N\): expected an integer.*"4x"' \
  "$bin" run c.json --shard 0/4x
refuse "--shard i >= N" '--shard: expected i/N with 0 <= i < N, got "4/4"' \
  "$bin" run c.json --shard 4/4
refuse "--shard no slash" '--shard: expected i/N' "$bin" run c.json --shard 3
refuse "--threads overflow" 'threads.*"99999999999999999999" is outside \[0, 4096\]' \
  "$bin" run c.json --threads 99999999999999999999
refuse "--threads trailing text" 'threads.*expected an integer' "$bin" run c.json --threads 2x
refuse "--threads above the config's range" 'threads.*4097 is outside \[0, 4096\]' \
  "$bin" run c.json --threads 4097
refuse "--isolate-timeout nan" 'isolate-timeout.*"nan" is not a finite number' \
  "$bin" run c.json --isolate --isolate-timeout nan
refuse "--isolate-memory overflow" 'isolate-memory.*is outside' \
  "$bin" run c.json --isolate --isolate-memory 18446744073709551617
refuse "--start overflow (was echoed as 1215752191)" '--start \(x\): 99999999999 is outside \[0, 8192\]' \
  "$bin" plan --map m.map --start 99999999999,0 --goal 2,2
refuse "--start negative" '--start \(y\): -1 is outside' "$bin" plan --map m.map --start 0,-1 --goal 2,2
refuse "--goal trailing text" '--goal \(y\): expected an integer.*"2 and more"' \
  "$bin" plan --map m.map --start 0,0 --goal "2,2 and more"
refuse "plan --seed -1" 'seed.*-1 is outside \[0, 9007199254740992\]' "$bin" plan --seed -1
refuse "plan --seed above the config's range" 'seed.*9007199254740993 is outside' \
  "$bin" plan --seed 9007199254740993
refuse "plan --map-index -1" 'map-index.*-1 is outside \[0, 9999999\]' "$bin" plan --map-index -1
refuse "plan --map-index 1e3" 'map-index.*expected an integer' "$bin" plan --map-index 1e3
refuse "plan --density nan" 'density.*"nan" is not a finite number' "$bin" plan --density nan
refuse "plan --density beyond the config's range" 'density.*0.96 is outside \[0, 0.95\]' \
  "$bin" plan --density 0.96
printf '{"sizes": [16], "densities": [0.96], "planners": ["astar"]}' >d.json
refuse "config density beyond the same range" 'densities\[0\]: 0.96 is outside \[0, 0.95\]' \
  "$bin" validate d.json
refuse "plan --size overflow" '--size: 99999999999 is outside \[2, 8192\]' "$bin" plan --size 99999999999
refuse "plan --size negative height" '--size \(height\): -3 is outside' "$bin" plan --size 16x-3
refuse "plan --size trailing text" '--size \(height\): expected an integer' "$bin" plan --size 16x16x
refuse "plan --clearance inf" 'clearance.*"inf" is not a finite number' "$bin" plan --clearance inf
refuse "scen --tolerance nan (was 0 mismatches)" 'tolerance.*"nan" is not a finite number' \
  "$bin" scen m.map m.scen --tolerance nan
refuse "scen --tolerance -1" 'tolerance.*-1 is outside \[0, 1\]' "$bin" scen m.map m.scen --tolerance -1
refuse "--param integer past 2^63" 'max_iterations: 18446744073709551615 is outside' \
  "$bin" plan --planner rrt --param max_iterations=18446744073709551615
refuse "--param nan" 'diagonal_cost: expected a number, got "nan"' "$bin" plan --param diagonal_cost=nan
refuse "worker --memory-mb -5" 'memory-mb.*-5 is outside' "$bin" worker --memory-mb -5

# What is accepted still works, and a leading zero is decimal, not octal.
if "$bin" plan --size 016 --seed 010 --map-index 0 --density 2.5e-1 --json --no-ascii >p.json 2>err.txt &&
  $py -c 'import json; d=json.load(open("p.json"))["map"]; assert d["width"]==16 and d["seed"]==10, d' ; then
  ok "plan takes 016, 010 and 2.5e-1 as 16, 10 and 0.25"
else
  bad "plan with valid numbers"; cat err.txt
fi
if "$bin" scen m.map m.scen --tolerance 1e-5 >/dev/null 2>err.txt; then
  ok "scen --tolerance 1e-5"
else
  bad "scen --tolerance 1e-5"; cat err.txt
fi

# --threads beyond the CPUs: the sweep runs on the CPUs this process may use, says so, and the
# report's environment gives that number (oneTBB never runs more).
cpus=$(nproc)
if "$bin" run c.json --threads 4096 >out.txt 2>err.txt &&
  grep -q "4096 threads asked for; $cpus run" err.txt &&
  grep -q "on $cpus threads" out.txt &&
  $py -c "import json,sys; e=json.load(open('r.json'))['environment']; assert e['threads']==$cpus, e"; then
  ok "--threads 4096 on $cpus CPUs runs and reports $cpus"
else
  bad "--threads 4096"; cat err.txt out.txt
fi

finish test_strict_cli
