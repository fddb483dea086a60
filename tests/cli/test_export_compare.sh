#!/usr/bin/env bash
# export (SQLite), run --db, compare, the progress lines of a stderr that is not a terminal,
# --version and the list forms. Usage: test_export_compare.sh AGVBENCH SOURCE_DIR
set -u
bin=$1
src=$2
source "$(dirname "$0")/lib.sh"
expect_exit() {  # NAME CODE COMMAND...
  local name=$1 code=$2
  shift 2
  "$@" >out.txt 2>err.txt
  local got=$?
  cp out.txt last.out  # for the checks that follow (check itself writes out.txt and err.txt)
  cp err.txt last.err
  if [ "$got" -eq "$code" ]; then ok "$name"; else bad "$name (exit $got, expected $code)"; cat out.txt err.txt | tail -20; fi
}
q() { sqlite3 -batch -noheader results.db "$1"; }

# The quick sweep's journal shape, stderr redirected to a file (not a terminal). A sanitized
# build (AGV_SANITIZED, tests/CMakeLists.txt) sweeps its shape at 8 maps per cell instead of 20:
# the same paths at two fifths of the cost (1,728 runs, still past the file-size limit below).
cfg=$src/configs/quick.json
maps=20
if [ "${AGV_SANITIZED:-0}" = 1 ]; then
  maps=8
  cfg=$PWD/quick8.json
  $py -c "import json,sys; c=json.load(open(sys.argv[1])); c['maps_per_cell']=8; json.dump(c, open(sys.argv[2],'w'))" "$src/configs/quick.json" "$cfg"
fi
quick_runs=$((4 * 2 * 3 * maps * 9))
check "run the quick config with a journal" "$bin" run "$cfg" --threads 2 --out quick.json --runs-out quick.jsonl
cp err.txt quick.err
check "progress: a line per 5 % of the runs on a stderr that is not a terminal" $py -c '
import re, sys
lines = [l for l in open("quick.err") if l.startswith("agvbench: progress ")]
pat = re.compile(r"agvbench: progress (\d+)/(\d+) runs \((\d+\.\d)%\), \d+\.\d runs/s, \d+ s elapsed, ETA (\d+ s|-)$")
done = [int(pat.match(l.rstrip("\n")).group(1)) for l in lines]
total = int(pat.match(lines[0].rstrip("\n")).group(2))
assert total == int(sys.argv[1]), total
assert done == sorted(done) and done[-1] == total, done
steps = {d * 20 // total for d in done}
assert steps >= set(range(1, 21)), sorted(steps)
assert "\r" not in open("quick.err").read()
' "$quick_runs"
lines=$($py "$journal_check" --count quick.jsonl)
# The report scripts recompute the hash the records carry (reports/agvreports/runs.py): the same
# as the engine's on a real sweep, floats and planner parameters included.
check "the report scripts' config hash is the engine's" $py -c "
import json, sys
sys.dont_write_bytecode = True
sys.path.insert(0, sys.argv[1] + '/reports')
from agvreports.runs import config_hash
want = json.loads(open(sys.argv[3]).readline())['config_hash']
sys.exit(0 if config_hash(json.load(open(sys.argv[2]))['config']) == want else 1)" "$src" quick.json quick.jsonl
check "export the quick journal" "$bin" export quick.jsonl --config "$cfg" --sqlite results.db
check "select count(*) from runs = the journal's run records ($lines)" test "$(q 'select count(*) from runs')" = "$lines"
check "one experiment, its config hash, date and environment" test "$(q "select count(*) from experiments where name = 'quick' and length(config_hash) = 16 and created_utc like '____-__-__T__:__:__Z' and json_extract(environment_json, '\$.load_average') is not null")" = 1
check "runs queryable by planner, cell and metric" test "$(q "select count(*) from run_values where planner = 'astar' and cell = 'uniform/32x32/0.1' and metric = 'path_length'")" = "$maps"
check "every successful run has its path_length" test "$(q "select count(*) from runs r where outcome = 'success' and not exists (select 1 from run_metrics m where m.run_id = r.run_id and m.metric = 'path_length')")" = 0
check "paired results: every planner but the baseline in every cell" test "$(q "select count(distinct cell_id || '/' || planner_id) from paired where metric = 'path_length'")" = $((24 * 8))
check "the journal's outcomes by planner, the same in the database" $py -c '
import json, os, sqlite3, subprocess, sys, collections
runs = subprocess.check_output([sys.executable, os.environ["AGV_JOURNAL_CHECK"], "--dump", "quick.jsonl"], text=True)
j = collections.Counter((r["planner"], r["outcome"]) for r in map(json.loads, runs.splitlines()))
db = sqlite3.connect("results.db")
d = collections.Counter({(p, o): n for p, o, n in db.execute("select p.label, r.outcome, count(*) from runs r join planners p using (experiment_id, planner_id) group by 1, 2")})
assert j == d, (j, d)
'
expect_exit "the same sweep exported twice is refused (exit 2), nothing written" 2 "$bin" export quick.jsonl --config "$cfg" --sqlite results.db
check "... and named" grep -q "experiment 1 already holds this sweep" last.err
check "... the database unchanged" test "$(q 'select count(*) from runs')" = "$lines"

cat >tiny.json <<'JSON'
{"name": "tiny", "seed": 3, "generators": ["uniform", "maze"], "sizes": [24], "densities": [0.1, 0.3],
 "maps_per_cell": 6, "planners": ["dijkstra", "astar", "ma_star"], "baseline": "dijkstra"}
JSON
check "run --db appends a second sweep as a second experiment" "$bin" run tiny.json --out tiny1.json --runs-out tiny1.jsonl --db results.db --quiet
check "two experiments, runs of each" test "$(q "select group_concat(n) from (select count(*) n from runs group by experiment_id order by experiment_id)")" = "$lines,72"
check "run --db writes what export writes" sh -c "'$bin' export tiny1.jsonl --config tiny.json --sqlite other.db >/dev/null && test \"\$(sqlite3 other.db 'select count(*) from runs')\" = 72 && test \"\$(sqlite3 other.db 'select count(*) from run_metrics')\" = \"\$(sqlite3 results.db 'select count(*) from run_metrics where run_id in (select run_id from runs where experiment_id = 2)')\""
cat >msg.json <<'JSON'
{"name": "msg", "seed": 3, "generators": ["maze"], "sizes": [24], "densities": [0.3],
 "maps_per_cell": 4, "planners": ["astar", {"name": "rrt", "params": {"max_iterations": 10}}]}
JSON
check "failure messages reach the database (run --db and export)" sh -c "'$bin' run msg.json --out msg.report --runs-out msg.jsonl --db msg.db --quiet && '$bin' export msg.jsonl --config msg.json --sqlite msg2.db >/dev/null && n=\$(grep -c '\"message\"' msg.jsonl) && test \$n -gt 0 && for d in msg.db msg2.db; do test \"\$(sqlite3 \$d \"select count(*) from runs where message like 'max_iterations%'\")\" = \$n || exit 1; done"
check "... and without a journal (run --db hands them over as the runs finish)" sh -c "'$bin' run msg.json --out msg3.report --db msg3.db --quiet && n=\$(grep -c '\"message\"' msg.jsonl) && test \"\$(sqlite3 msg3.db \"select count(*) from runs where message like 'max_iterations%'\")\" = \$n"
check "a small database of one sweep" "$bin" export tiny1.jsonl --config tiny.json --sqlite small.db
expect_exit "a write that fails (file-size limit) is exit 1" 1 bash -c "ulimit -f 600; exec '$bin' export quick.jsonl --config '$cfg' --sqlite small.db"
check "... naming the database" grep -q -- '--sqlite "small.db": ' last.err
check "... which holds what it held, intact" test "$(sqlite3 small.db 'pragma integrity_check; select count(*) from experiments; select count(*) from runs' | tr '\n' ' ')" = "ok 1 72 "
printf 'not a database, a user file\n' >notes.txt
expect_exit "export into a file that is not a database: exit 2" 2 "$bin" export tiny1.jsonl --config tiny.json --sqlite notes.txt
check "... the file left as it was" test "$(cat notes.txt)" = "not a database, a user file"
expect_exit "run --db into a file that is not a database: exit 2 before the sweep" 2 "$bin" run tiny.json --out never.json --db notes.txt --quiet
check "... no report written, the file as it was" sh -c "test ! -e never.json && test \"\$(cat notes.txt)\" = 'not a database, a user file'"
expect_exit "export over its own journal: exit 2" 2 "$bin" export tiny1.jsonl --config tiny.json --sqlite tiny1.jsonl
expect_exit "export into a missing folder: exit 2" 2 "$bin" export tiny1.jsonl --config tiny.json --sqlite nowhere/r.db
: >empty.jsonl
expect_exit "export of an empty journal: exit 2" 2 "$bin" export empty.jsonl --config tiny.json --sqlite new.db
expect_exit "export of a journal of another config: exit 2" 2 "$bin" export quick.jsonl --config tiny.json --sqlite new.db

# Issue 28, class 8. A database another connection holds locked: exit 1 after the wait (shortened
# here by AGVBENCH_SQLITE_WAIT_MS), named as locked, not as another application's or empty.
cp small.db locked.db
cp small.db locked.orig
coproc LOCK { sqlite3 -batch locked.db; }
# Copies of the coprocess's pipes and pid: bash unsets LOCK and LOCK_PID once it has ended.
lock_pid=$LOCK_PID
exec {lock_in}>&"${LOCK[1]}" {lock_out}<&"${LOCK[0]}"
echo "BEGIN EXCLUSIVE; SELECT 'held';" >&"$lock_in"
read -r held <&"$lock_out"  # the lock is taken once sqlite3 answers
expect_exit "export into a locked database: exit 1 (held: $held)" 1 \
  env AGVBENCH_SQLITE_WAIT_MS=300 "$bin" export tiny1.jsonl --config tiny.json --sqlite locked.db
check "... named as locked by another connection" grep -q -- '--sqlite "locked.db": is locked by another connection, still after 0.3 s' last.err
expect_exit "run --db into a locked database: exit 1" 1 \
  env AGVBENCH_SQLITE_WAIT_MS=300 "$bin" run tiny.json --out locked.report --db locked.db --quiet
check "... named as locked" grep -q -- '--db "locked.db": is locked by another connection' last.err
echo "COMMIT;" >&"$lock_in"
exec {lock_in}>&- {lock_out}<&-
eval "exec ${LOCK[1]:-$lock_in}>&-" 2>/dev/null  # the coprocess's own write end, if still open
wait "$lock_pid" 2>/dev/null
check "... and left as it was" cmp locked.db locked.orig
expect_exit "a bad AGVBENCH_SQLITE_WAIT_MS: exit 2" 2 \
  env AGVBENCH_SQLITE_WAIT_MS=soon "$bin" export tiny1.jsonl --config tiny.json --sqlite locked.db
check "... naming it" grep -q 'AGVBENCH_SQLITE_WAIT_MS: "soon" is not a whole number' last.err
# A damaged database (the header of its first b-tree page overwritten): exit 2, named as damaged,
# left as it is.
cp small.db damaged.db
printf 'xxxxxxxx' | dd of=damaged.db bs=1 seek=100 conv=notrunc 2>/dev/null
cp damaged.db damaged.orig
expect_exit "export into a damaged database: exit 2" 2 "$bin" export tiny1.jsonl --config tiny.json --sqlite damaged.db
check "... named as damaged" grep -q -- '--sqlite "damaged.db": is a damaged SQLite database' last.err
expect_exit "run --db into a damaged database: exit 2 before the sweep" 2 "$bin" run tiny.json --out damaged.report --db damaged.db --quiet
check "... no report written" test ! -e damaged.report
check "... and the database left as it was" cmp damaged.db damaged.orig

# compare
check "a second run of the same config" "$bin" run tiny.json --out tiny2.json --runs-out tiny2.jsonl --quiet
expect_exit "compare two runs of one config: exit 0" 0 "$bin" compare tiny1.json tiny2.json --runs-before tiny1.jsonl --runs-after tiny2.jsonl
check "... no non-timing difference, a paired test per planner and cell" sh -c "grep -q 'non-timing results: identical' last.out && test \$(grep -c ' wilcoxon ' last.out) = 12 && grep -q '^overall: geometric mean of 12' last.out"
expect_exit "compare without journals: exit 0, ratios of medians" 0 "$bin" compare tiny1.json tiny2.json
check "compare --json" sh -c "'$bin' compare tiny1.json tiny2.json --runs-before tiny1.jsonl --runs-after tiny2.jsonl --json | $py -c 'import json,sys; d=json.load(sys.stdin); assert d[\"exit_code\"]==0 and d[\"differences\"]==[] and len(d[\"timing\"])==12 and [p[\"planner\"] for p in d[\"planners\"]]==[\"dijkstra\",\"astar\",\"ma_star\"] and all(t[\"test\"]==\"wilcoxon\" and t[\"pairs\"]==6 for t in d[\"timing\"])'"
$py - <<'PY'
import json
c = json.load(open("tiny.json"))
c["planners"] = ["dijkstra", {"name": "astar", "params": {"heuristic": "octile"}}, "ma_star"]
json.dump(c, open("tiny_h.json", "w"))
PY
check "a run after changing an A* parameter" "$bin" run tiny_h.json --out tiny_h.json.report --runs-out tiny_h.jsonl --quiet
expect_exit "compare after the A* change: exit 1" 1 "$bin" compare tiny1.json tiny_h.json.report --runs-before tiny1.jsonl --runs-after tiny_h.jsonl
check "... the parameter named, the differences listed under astar only" $py -c '
text = open("last.out").read()
assert "astar: heuristic \"euclidean\" -> \"octile\"" in text, text[:500]
block = text.split("non-timing differences:")[1].split("planning time")[0]
heads = [l.strip() for l in block.splitlines()[1:] if l.startswith("  ") and not l.startswith("    ")]
assert heads == ["astar"], heads
assert "search_expansions" in block
'
check "... and in --json" sh -c "'$bin' compare tiny1.json tiny_h.json.report --json | $py -c 'import json,sys; d=json.load(sys.stdin); assert d[\"exit_code\"]==1 and d[\"differences\"] and {x[\"planner\"] for x in d[\"differences\"]}=={\"astar\"}'"
$py -c '
import json
r = json.load(open("tiny2.json"))
for c in r["cells"]:
    for p in c["planners"]:
        p["timing"]["plan_time_ns"]["median"] *= 3
json.dump(r, open("slow.json", "w"))
'
expect_exit "timing never fails by default" 0 "$bin" compare tiny1.json slow.json
expect_exit "--fail-on-regression 50: three times slower fails" 1 "$bin" compare tiny1.json slow.json --fail-on-regression 50
check "... named REGRESSION" grep -q REGRESSION last.out
$py -c '
import json
c = json.load(open("tiny.json")); c["seed"] = 4; json.dump(c, open("seed4.json", "w"))
'
check "a run of another seed" "$bin" run seed4.json --out seed4.report --quiet
expect_exit "compare of configs that differ beyond planner parameters: exit 2" 2 "$bin" compare tiny1.json seed4.report
check "... saying what differs" grep -q "seed 3 -> 4" last.err
expect_exit "compare a journal as a report: exit 2" 2 "$bin" compare tiny1.json tiny1.jsonl
expect_exit "compare a missing file: exit 2" 2 "$bin" compare tiny1.json missing.json
# A damaged report (a field of another type): exit 2 naming the field, not the JSON library's error.
$py -c 'import json, sys; d = json.load(open(sys.argv[1])); d["cells"][0]["cell"] = 1; json.dump(d, open(sys.argv[2], "w"))' tiny2.json odd_cell.json
expect_exit "compare a report whose cell name is a number: exit 2" 2 "$bin" compare tiny1.json odd_cell.json --runs-before tiny1.jsonl --runs-after tiny2.jsonl
check "... naming the field" grep -q 'AFTER: cells\[0\].cell: expected a string' last.err
expect_exit "--runs-before without --runs-after: exit 2" 2 "$bin" compare tiny1.json tiny2.json --runs-before tiny1.jsonl
expect_exit "journals swapped with another config's: exit 2" 2 "$bin" compare tiny1.json tiny2.json --runs-before quick.jsonl --runs-after tiny2.jsonl
# Issue 49, class 5: two sweeps of one config share the config hash but not their times; each
# report names its sweep (environment.sweep_ids), each journal segment's header its own.
expect_exit "journals of the other sweep of the same config: exit 2" 2 "$bin" compare tiny1.json tiny2.json --runs-before tiny2.jsonl --runs-after tiny1.jsonl
check "... naming both sweeps" grep -q -- '--runs-before "tiny2.jsonl": holds sweep [0-9a-f]\{16\}, but BEFORE "tiny1.json" reports sweep [0-9a-f]\{16\}: not this report' last.err
expect_exit "check_claims.py with the other sweep's journal: exit 2" 2 $py "$src/reports/check_claims.py" tiny1.json tiny2.jsonl
check "... naming it" grep -q 'tiny2.jsonl: holds sweep [0-9a-f]\{16\}, but the report is of sweep' last.err
expect_exit "plot.py --runs with the other sweep's journal: exit 2" 2 $py "$src/reports/plot.py" tiny1.json pictures --runs tiny2.jsonl
check "... naming it, nothing drawn" sh -c "grep -q 'tiny2.jsonl: holds sweep' last.err && test ! -e pictures"
expect_exit "--fail-on-regression -5: exit 2" 2 "$bin" compare tiny1.json tiny2.json --fail-on-regression -5

# --version and list forms
check "--version: version, git revision, compiler" sh -c "'$bin' --version | grep -Eq '^agvbench [0-9]+\.[0-9]+\.[0-9]+ \(git ([0-9a-f]+(-dirty)?|unknown), (gcc|clang) '"
check "list astar: that planner only" sh -c "'$bin' list astar >l.txt && grep -q '^astar  -  ' l.txt && ! grep -q '^dijkstra  -  ' l.txt && ! grep -q '^generators' l.txt"
check "list astar rooms --json" sh -c "'$bin' list astar rooms --json | $py -c 'import json,sys; d=json.load(sys.stdin); assert [p[\"name\"] for p in d[\"planners\"]]==[\"astar\"] and [g[\"name\"] for g in d[\"generators\"]]==[\"rooms\"]'"
expect_exit "list nosuch: exit 2" 2 "$bin" list astar nosuch
check "... naming it" grep -q '"nosuch" is neither a planner, a generator nor a map source' last.err
check "list --brief: one line per planner, generator and map source" sh -c "test \$('$bin' list --brief | wc -l) = \$('$bin' list --json | $py -c 'import json,sys; d=json.load(sys.stdin); print(len(d[\"planners\"]) + len(d[\"generators\"]) + len(d[\"map_sources\"]))')"
check "summary table names µs" sh -c "'$bin' run tiny.json --out t3.json | grep -q 'median µs'"

finish cli_export_compare
