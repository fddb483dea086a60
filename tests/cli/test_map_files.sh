#!/usr/bin/env bash
# Map sources through the command line (issue 16): a sweep of MovingAI map files and occupancy
# images (paths relative to the config's folder, from any working directory) gives the same
# report sharded and merged, resumed, and under --isolate; a changed map file makes resume
# refuse by the file's name; bad map files are exit 2 naming the file (and line), for `run` and
# `validate` alike, with no report written. Usage: test_map_files.sh AGVBENCH SOURCE_DIR
set -u
bin=$1
src=$2
same=$src/slurm/same_report.py
source "$(dirname "$0")/lib.sh"

mkdir -p sweep/maps other
$py - <<'EOF_PY'
import random
random.seed(3)
for k in range(3):
    w, h = 20 + 4 * k, 18 + 3 * k
    rows = ["".join("@" if random.random() < 0.2 else "." for _ in range(w)) for _ in range(h)]
    with open(f"sweep/maps/m{k}.map", "w") as f:
        f.write(f"type octile\nheight {h}\nwidth {w}\nmap\n" + "\n".join(rows) + "\n")
# A PGM occupancy image with its map_server description.
w, h = 25, 21
pixels = bytes(0 if random.random() < 0.15 else 254 for _ in range(w * h))
with open("sweep/maps/floor.pgm", "wb") as f:
    f.write(b"P5\n%d %d\n255\n" % (w, h) + pixels)
with open("sweep/maps/floor.yaml", "w") as f:
    f.write("image: floor.pgm\nresolution: 0.05\norigin: [0.0, 0.0, 0.0]\nnegate: 0\n"
            "occupied_thresh: 0.65\nfree_thresh: 0.196\n")
EOF_PY
cat >sweep/config.json <<'JSON'
{"name": "map-files", "seed": 11,
 "generators": [{"name": "movingai", "params": {"files": ["maps/*.map"]}},
                {"name": "image", "params": {"files": ["maps/floor.yaml"]}}],
 "maps_per_cell": 15, "map": {"endpoints": "random", "min_distance": 8},
 "planners": ["astar", "ma_star", "rrt"], "report": "unused.json"}
JSON
# 4 files x 15 maps x 3 planners.
expected=$((4 * 15 * 3))

"$bin" validate sweep/config.json >/dev/null 2>&1 && ok "validate accepts the file sweep" || bad "validate refuses the file sweep"
"$bin" run sweep/config.json --threads 2 --out full.json --runs-out full.jsonl --quiet || { bad "file sweep run"; exit 1; }
$py - "$expected" <<'EOF_PY' && ok "report: a cell per file, named by it, $expected runs" || bad "report cells or coverage"
import json, sys
r = json.load(open("full.json"))
cells = [c["cell"] for c in r["cells"]]
want = ["movingai/m0.map", "movingai/m1.map", "movingai/m2.map", "image/floor.yaml"]
ok = cells == want and r["coverage"]["runs_present"] == int(sys.argv[1]) and r["complete"]
print(cells, r["coverage"])
sys.exit(0 if ok else 1)
EOF_PY

# From another working directory: the files are found relative to the config.
(cd other && "$bin" run ../sweep/config.json --threads 1 --out ../other.json --quiet) &&
  $py "$same" full.json other.json >/dev/null && ok "run from another folder gives the same report" ||
  bad "run from another folder: $($py "$same" full.json other.json 2>&1)"

for i in 0 1 2; do
  "$bin" run sweep/config.json --threads 2 --shard "$i/3" --out "shard_$i.json" \
    --runs-out "shard_$i.jsonl" --quiet || bad "shard $i/3 exit $?"
done
"$bin" merge shard_0.jsonl shard_1.jsonl shard_2.jsonl --config sweep/config.json --out merged.json >/dev/null
code=$?
[ $code -eq 0 ] && ok "merge of 3 shards exits 0" || bad "merge exits $code"
$py "$same" full.json merged.json >/dev/null && ok "merged report equals the single run" ||
  bad "merged report differs: $($py "$same" full.json merged.json)"

half=$((expected / 2))
head -n "$half" full.jsonl >part.jsonl
cp part.jsonl part_changed.jsonl
cp part.jsonl part.orig
"$bin" run sweep/config.json --threads 2 --resume part.jsonl --out resumed.json --quiet
code=$?
[ $code -eq 0 ] && ok "resume exits 0" || bad "resume exits $code"
$py "$same" full.json resumed.json >/dev/null && ok "resumed report equals the single run" ||
  bad "resumed report differs: $($py "$same" full.json resumed.json)"
$py "$journal_check" part.jsonl "$expected" >/dev/null && ok "resumed journal holds each run once" ||
  bad "resumed journal: $($py "$journal_check" part.jsonl "$expected")"

"$bin" run sweep/config.json --threads 2 "${isolate[@]}" --out isolated.json --quiet
code=$?
[ $code -eq 0 ] && $py "$same" full.json isolated.json >/dev/null && ok "--isolate gives the same report" ||
  bad "--isolate: exit $code, $($py "$same" full.json isolated.json 2>&1)"

# A map file changed after the journal began: another sweep, and resume says which file.
sed -i '5s/^./@/' sweep/maps/m0.map
"$bin" run sweep/config.json --resume part_changed.jsonl --out changed.json --quiet 2>err.txt
code=$?
{ [ $code -eq 2 ] && grep -q 'map file sweep/maps/m0.map changed since the journal was written' err.txt &&
  [ ! -e changed.json ]; } && ok "resume refuses a changed map file by name (exit 2)" ||
  bad "changed map file: exit $code, $(cat err.txt)"
cmp -s part.orig part_changed.jsonl && ok "its journal is left as it was" || bad "journal changed"

# Bad map files: exit 2 naming the file (and line), from run and validate, no report.
refused() {  # NAME PATTERN CONFIG
  for cmd in run validate; do
    if [ $cmd = run ]; then
      "$bin" run "$3" --out refused.json --quiet 2>err.txt
    else
      "$bin" validate "$3" >/dev/null 2>err.txt
    fi
    code=$?
    { [ $code -eq 2 ] && grep -q -- "$2" err.txt && [ ! -e refused.json ]; } && ok "$1 ($cmd): exit 2" ||
      bad "$1 ($cmd): exit $code, $(cat err.txt)"
  done
}
bad_config() {  # SOURCE FILES-JSON
  echo "{\"generators\": [{\"name\": \"$1\", \"params\": {\"files\": $2}}], \"planners\": [\"astar\"], \"report\": \"unused.json\"}" >sweep/bad.json
}
bad_config movingai '["maps/nothing*.map"]'
refused "a pattern matching nothing" 'files\[0\]: "maps/nothing\*.map" matches no file' sweep/bad.json
bad_config movingai '["maps/absent.map"]'
refused "a missing file" '"maps/absent.map" matches no file (no such file)' sweep/bad.json
# A NUL in a name: glob() would read the shorter name (maps/m0.map, which exists); and the same
# anywhere else in a config (a label).
bad_config movingai '["maps/m0.map\u0000.txt"]'
refused "a file name holding a NUL" 'generators\[0\].params.files\[0\]: "maps/m0.map\\u0000.txt" holds a NUL character' sweep/bad.json
echo '{"planners": [{"name": "astar", "label": "a\u0000b"}], "report": "unused.json"}' >sweep/bad.json
refused "a label holding a NUL" 'planners\[0\].label: "a\\u0000b" holds a NUL character' sweep/bad.json
printf 'type octile\nheight 2\nwidth 2\nmap\n..\n.?\n' >sweep/maps/broken.map
bad_config movingai '["maps/broken.map"]'
refused "a malformed map line" 'sweep/maps/broken.map:6:' sweep/bad.json
printf 'image: floor.pgm\nresolution: 0.05\nnegate: 0\ncolour: red\n' >sweep/maps/extra.yaml
bad_config image '["maps/extra.yaml"]'
refused "an unknown yaml key" 'sweep/maps/extra.yaml:4: unknown key "colour"' sweep/bad.json
printf 'P5\n25 21\n255\nshort' >sweep/maps/short.pgm
bad_config image '["maps/short.pgm"]'
refused "a truncated PGM" 'sweep/maps/short.pgm:3: the samples end' sweep/bad.json

finish test_map_files
