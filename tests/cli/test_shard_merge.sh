#!/usr/bin/env bash
# Sharding and merge (issue 8), with a scoped planner in the sweep (issue 5's "only"): shards
# 0..3 of 4 merged equal the unsharded report (non-timing fields); a missing shard is reported
# as incomplete coverage (exit 1), never silently averaged; one shard's journal resumed without
# --shard completes the sweep to the same report, even when the journal's last record lost its
# newline; a journal record for a run outside its
# planner's scope is refused (exit 2). Usage: test_shard_merge.sh AGVBENCH SOURCE_DIR
set -u
bin=$1
src=$2
same=$src/slurm/same_report.py
source "$(dirname "$0")/lib.sh"

cat >config.json <<'JSON'
{"name": "shard-test", "seed": 5, "generators": ["uniform", "maze"], "sizes": [24, 40],
 "densities": [0.1, 0.3], "maps_per_cell": 30,
 "planners": ["astar", "ma_star",
              {"name": "rrt", "only": {"sizes": [24], "densities": [0.1], "maps_per_cell": 12}}],
 "report": "unused.json"}
JSON
# 8 cells x 30 maps x 2 planners, and rrt on 2 cells x 12 maps.
expected=$((8 * 30 * 2 + 2 * 12))

"$bin" run config.json --threads 2 --out full.json --quiet || { bad "unsharded run"; exit 1; }
runs=$($py -c 'import json,sys; c=json.load(open("full.json"))["coverage"]; print(c["runs_expected"], c["runs_present"])')
[ "$runs" = "$expected $expected" ] && ok "unsharded coverage $runs" || bad "unsharded coverage: $runs, want $expected"

for i in 0 1 2 3; do
  "$bin" run config.json --threads 2 --shard "$i/4" --out "shard_$i.json" --runs-out "shard_$i.jsonl" \
    --quiet || bad "shard $i/4 exit $?"
done
lines=$(cat shard_*.jsonl | grep -c '"planner":')
[ "$lines" -eq "$expected" ] && ok "4 shards wrote $lines records" || bad "4 shards wrote $lines records, want $expected"

"$bin" merge shard_0.jsonl shard_1.jsonl shard_2.jsonl shard_3.jsonl --config config.json \
  --out merged.json >merge.log
code=$?
[ $code -eq 0 ] && ok "merge of 4 shards exits 0" || bad "merge of 4 shards exits $code: $(cat merge.log)"
$py "$same" full.json merged.json >/dev/null && ok "merged report equals the unsharded one" ||
  bad "merged report differs: $($py "$same" full.json merged.json)"

# The merged report names the four shards' sweeps: their journals together are its journal, one
# of them alone is not (issue 49, class 5).
cat shard_0.jsonl shard_1.jsonl shard_2.jsonl shard_3.jsonl >all_shards.jsonl
"$bin" compare merged.json merged.json --runs-before all_shards.jsonl --runs-after shard_0.jsonl \
  shard_1.jsonl shard_2.jsonl shard_3.jsonl >/dev/null 2>err.txt &&
  ok "compare a merged report with its shards' journals, concatenated or not" ||
  bad "compare with the shards' journals: $(cat err.txt)"
"$bin" compare merged.json merged.json --runs-before shard_0.jsonl --runs-after all_shards.jsonl \
  >/dev/null 2>err.txt
code=$?
[ $code -eq 2 ] && grep -q 'holds sweep [0-9a-f]*, but BEFORE "merged.json" reports sweep [0-9a-f]*, [0-9a-f]*, [0-9a-f]*, [0-9a-f]*:' err.txt &&
  ok "one shard's journal is not the merged report's (exit 2)" || bad "one shard's journal: exit $code, $(cat err.txt)"

"$bin" merge shard_0.jsonl shard_1.jsonl shard_3.jsonl --config config.json --out partial.json \
  >partial.log
code=$?
[ $code -eq 1 ] && ok "merge without shard 2 exits 1" || bad "merge without shard 2 exits $code"
grep -q INCOMPLETE partial.log && ok "merge says INCOMPLETE" || bad "merge does not say INCOMPLETE: $(cat partial.log)"
present=$(grep -c '"planner":' shard_2.jsonl)
$py - "$expected" "$present" <<'EOF_PY' && ok "partial report: complete=false, coverage counts the missing shard" || bad "partial report coverage"
import json, sys
expected, missing = int(sys.argv[1]), int(sys.argv[2])
r = json.load(open("partial.json"))
c = r["coverage"]
# Map tasks t with t % 4 == 2: 240 map tasks in all, a quarter of them.
ok = (r["complete"] is False and c["runs_expected"] == expected and
      c["runs_present"] == expected - missing and c["maps_missing"] == 240 // 4)
print(c, r["complete"])
sys.exit(0 if ok else 1)
EOF_PY

# The journal as a kill between a record and its newline leaves it: the record is run again,
# not lost from the journal.
head -c -1 shard_1.jsonl >resumed.jsonl
"$bin" run config.json --threads 2 --resume resumed.jsonl --out resumed.json --quiet
code=$?
[ $code -eq 0 ] && ok "resume from one shard's journal exits 0" || bad "resume exits $code"
$py "$same" full.json resumed.json >/dev/null && ok "resumed report equals the unsharded one" ||
  bad "resumed report differs: $($py "$same" full.json resumed.json)"
lines=$(grep -c '"planner":' resumed.jsonl)
$py "$journal_check" resumed.jsonl "$expected" >/dev/null && ok "resumed journal has each run once ($lines)" || bad "resumed journal has $lines records, want $expected"

# An astar record relabelled as rrt on a map outside rrt's scope (size 40): the header, the map's
# record and the run, its planner index changed.
$py - shard_0.jsonl <<'EOF_PY' >foreign.jsonl
import json, sys
lines = [json.loads(l) for l in open(sys.argv[1])]
h = lines[0]
cell = [c["cell"] for c in h["cells"]].index("uniform/40x40/0.3")
labels = [p["label"] for p in h["planners"]]
for i, r in enumerate(lines):
    if r.get("cell") == cell and r.get("planner") == labels.index("astar"):
        m = [x for x in lines[:i] if x.get("record") == "map" and x["cell"] == cell and x["map_index"] == r["map_index"]]
        r["planner"] = labels.index("rrt")
        for x in (h, m[-1], r):
            print(json.dumps(x))
        break
EOF_PY
if [ -s foreign.jsonl ]; then
  "$bin" merge foreign.jsonl --config config.json --out foreign.json 2>err.txt >/dev/null
  code=$?
  { [ $code -eq 2 ] && grep -q 'not scheduled on this map' err.txt && [ ! -e foreign.json ]; } &&
    ok "out-of-scope record refused (exit 2, no report)" || bad "out-of-scope record: exit $code, $(cat err.txt)"
else
  bad "no astar record of uniform/40x40/0.3 in shard 0 to relabel"
fi

finish test_shard_merge
