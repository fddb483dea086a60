#!/usr/bin/env bash
# The happy paths of every subcommand, as a user types them (on MovingAI maps:
# test_scen_commands.sh). Usage: test_commands.sh AGVBENCH SOURCE_DIR
set -u
bin=$1
src=$2
source "$(dirname "$0")/lib.sh"

check "list --json parses and names astar and rooms" sh -c "'$bin' list --json | $py -c 'import json,sys; r=json.load(sys.stdin); assert set(r)=={\"planners\",\"generators\",\"map_sources\"}; assert [m[\"name\"] for m in r[\"map_sources\"]]==[\"movingai\",\"image\"]; assert any(p[\"name\"]==\"astar\" for p in r[\"planners\"]); assert all(\"params\" in p for p in r[\"planners\"] + r[\"generators\"]); g={x[\"name\"]: x for x in r[\"generators\"]}; assert [p[\"name\"] for p in g[\"rooms\"][\"params\"]]==[\"room_size\",\"door_width\"]'"
check "list prints parameters" sh -c "'$bin' list | grep -q 'corner_rule'"
check "list prints the generators" sh -c "'$bin' list | grep -q '^rooms  -  ' && '$bin' list | grep -q 'door_width = 2'"
check "plan --gen-param reaches the generator" sh -c "'$bin' plan --generator rooms --size 20 --density 0.2 --no-ascii --json | $py -c 'import json,sys; d=json.load(sys.stdin); assert d[\"map\"][\"params\"]=={\"door_width\":2,\"room_size\":8}' && '$bin' plan --generator rooms --size 20 --density 0.2 --gen-param room_size=4 --no-ascii --json | $py -c 'import json,sys; d=json.load(sys.stdin); assert d[\"map\"][\"params\"][\"room_size\"]==4'"
cat >rooms4.json <<'JSON'
{"name": "replay", "seed": 5, "generators": [{"name": "rooms", "params": {"room_size": 4}}],
 "sizes": [20], "densities": [0.2], "maps_per_cell": 2, "planners": ["astar"]}
JSON
check "plan --gen-param rebuilds the map a sweep cell produced" sh -c "'$bin' run rooms4.json --out rooms4.report.json --runs-out rooms4.jsonl --quiet && '$bin' plan --generator rooms --gen-param room_size=4 --size 20 --density 0.2 --seed 5 --map-index 1 --json >replay.json && '$bin' plan --generator rooms --size 20 --density 0.2 --seed 5 --map-index 1 --json >default.json && $py -c '
import json
recs = [r for r in map(json.loads, open(\"rooms4.jsonl\")) if r.get(\"map_index\") == 1]
m = [r for r in recs if r.get(\"record\") == \"map\"][0]
run = [r for r in recs if \"planner\" in r][0]
mine, other = (json.load(open(f)) for f in (\"replay.json\", \"default.json\"))
rows = mine[\"map\"][\"rows\"]
assert abs(sum(r.count(\"@\") for r in rows) / 400 - m[\"obstacle_fraction\"]) < 1e-12
assert run[\"mask\"] & 1, \"path_length is the first metric of the mask\"
assert mine[\"runs\"][0][\"metrics\"][\"path_length\"] == run[\"metrics\"][0]
assert other[\"map\"][\"rows\"] != rows, \"room_size did not reach the generator\"
'"
# From the checkout root, as the README runs it: the config's report folder (reports/out/, which
# ships with the checkout) must exist, as `run` would require.
check "validate the quick config" sh -c "cd '$src' && '$bin' validate configs/quick.json"
check "plan on a generated grid draws S, G and a path" sh -c "'$bin' plan --planner astar --planner dijkstra --size 24 --density 0.2 --seed 3 | grep -q 'S' && '$bin' plan --size 24 --density 0.2 | grep -q 'astar: success'"
check "plan --json-out writes a path document" sh -c "'$bin' plan --size 16 --density 0.1 --json-out p.json --no-ascii >/dev/null && $py -c 'import json; d=json.load(open(\"p.json\")); assert d[\"runs\"][0][\"outcome\"]==\"success\" and len(d[\"runs\"][0][\"path\"])>1'"
# The quick config's shape (every generator, size, density and planner) at 2 maps per cell: the
# path of a run, not its volume (the sweep suite has that), so that it stays short under ASan.
$py -c "import json,sys; c=json.load(open(sys.argv[1])); c['maps_per_cell']=2; json.dump(c, open('quick2.json','w'))" "$src/configs/quick.json"
check "run writes a report and a journal" sh -c "'$bin' run quick2.json --out r.json --runs-out r.jsonl --quiet && $py -c 'import json; r=json.load(open(\"r.json\")); assert r[\"schema_version\"]==2 and r[\"complete\"]' && test -s r.jsonl"
finish test_commands
