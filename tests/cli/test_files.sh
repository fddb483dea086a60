#!/usr/bin/env bash
# The user's files (issue 15): an output never replaces an input or another output, bad output
# paths are refused before anything is written, a journal holding records is never truncated, a
# failed journal write stops the sweep with exit 1 naming the journal, journals of another
# version are refused, file names that are not UTF-8 are written escaped, and a report's stale
# temporaries are removed.
# Usage: test_files.sh AGVBENCH_BINARY
set -u
bin=$1
src_dir=$(cd "$(dirname "$0")/../.." && pwd)
source "$(dirname "$0")/lib.sh"

config() {  # a small valid config; $1 = report path, $2 = maps per cell
  cat <<JSON
{"name": "files", "seed": 3, "sizes": [16], "densities": [0.1], "maps_per_cell": ${2:-3},
 "planners": ["astar", "dijkstra"], "report": "$1"}
JSON
}
config r.json >c.json
cp c.json c.orig

# The folder's entries (out.txt and err.txt aside): name, type, inode, size, modification time.
snapshot() {
  find . -maxdepth 1 ! -name . ! -name out.txt ! -name err.txt -printf '%f %y %i %s %T@\n' | sort
}

# refused NAME PATTERN COMMAND...: exit 2, stderr matching PATTERN, and every entry of the folder
# as it was (nothing replaced, truncated, created or left behind).
refused() {
  local name=$1 pattern=$2
  shift 2
  local before
  before=$(snapshot)
  "$@" >out.txt 2>err.txt
  local code=$?
  if [ $code -ne 2 ]; then
    bad "$name: exit $code, expected 2 ($(head -c 300 err.txt))"
  elif ! grep -qE -- "$pattern" err.txt; then
    bad "$name: message does not match /$pattern/: $(head -c 300 err.txt)"
  elif [ "$before" != "$(snapshot)" ]; then
    bad "$name: the folder changed: $(diff <(echo "$before") <(snapshot) | head -5)"
  else
    ok "$name: $(head -c 160 err.txt)"
  fi
  # Undo what a binary without these checks destroyed, so that each case stands on its own.
  cmp -s c.json c.orig || cp c.orig c.json
  tiny_map >m.map
}
tiny_map() { printf 'type octile\nheight 4\nwidth 4\nmap\n....\n....\n....\n....\n'; }
tiny_map >m.map

# Class 1: user files never destroyed.
refused "--out the config" '--out "c.json": is the config file' "$bin" run c.json --out c.json --quiet
refused "--out the config via .." '--out "sub/../c.json": is the config file' \
  sh -c "mkdir -p sub && '$bin' run c.json --out sub/../c.json --quiet; rc=\$?; rmdir sub; exit \$rc"
ln -s c.json link.json
refused "--out a symlink to the config" '--out "link.json": is the config file' \
  "$bin" run c.json --out link.json --quiet
refused "--runs-out the config" '--runs-out "c.json": is the config file' \
  "$bin" run c.json --runs-out c.json --quiet
refused "--resume the config" '--resume "c.json": is the config file' \
  "$bin" run c.json --resume c.json --quiet
refused "report = journal" '--runs-out "j.jsonl": is also the --out "j.jsonl"' \
  "$bin" run c.json --out j.jsonl --runs-out j.jsonl --quiet
refused "report = the resumed journal" '--resume "./j0.jsonl": is also the --out' \
  sh -c "touch j0.jsonl && '$bin' run c.json --out j0.jsonl --resume ./j0.jsonl --quiet; rc=\$?; rm j0.jsonl; exit \$rc"
refused "report folder missing" '--out "nowhere/r.json": its directory .* does not exist' \
  "$bin" run c.json --out nowhere/r.json --quiet
[ ! -e nowhere ] && ok "no folder created for a refused report" || bad "a folder was created"
config nowhere/r.json >cn.json
refused "config's report folder missing (validate too)" 'report "nowhere/r.json": its directory' \
  "$bin" validate cn.json
mkdir adir
refused "report is a directory" '--out "adir": is a directory' "$bin" run c.json --out adir --quiet
refused "journal is a device" '--runs-out "/dev/null": is a character device' \
  "$bin" run c.json --runs-out /dev/null --quiet
if [ "$(id -u)" != 0 ]; then
  mkdir ro && chmod 555 ro
  refused "read-only report folder" 'is not writable' "$bin" run c.json --out ro/r.json --quiet
  chmod 755 ro && rmdir ro
else
  echo "note read-only folder case skipped: root writes into any folder"
fi

"$bin" run c.json --out r.json --runs-out j.jsonl --quiet || bad "a plain run (exit $?)"
cp j.jsonl j.orig
refused "an existing journal is not truncated" '--runs-out "j.jsonl": already holds a journal .*--resume' \
  "$bin" run c.json --out r2.json --runs-out j.jsonl --quiet
config r.json | sed 's#"report"#"runs": "j.jsonl", "report"#' >cj.json
refused "the config's journal is not truncated (validate too)" 'runs "j.jsonl": already holds' \
  "$bin" validate cj.json
refused "a config error keeps the journal" 'map' \
  sh -c "sed 's#\"report\"#\"map\": {\"endpoints\": \"nowhere\"}, \"report\"#' c.json >bad.json; '$bin' run bad.json --out r3.json --runs-out j.jsonl --quiet; rc=\$?; rm bad.json; exit \$rc"
cp j.jsonl s0.jsonl
refused "merge --out one of its journals" '--out "s0.jsonl": is the journal' \
  "$bin" merge j.jsonl s0.jsonl --config c.json --out s0.jsonl
refused "merge --out its config" '--out "c.json": is the config file' \
  "$bin" merge j.jsonl --config c.json --out c.json
refused "plan --json-out the map" '--json-out "m.map": is the --map' \
  "$bin" plan --map m.map --start 0,0 --goal 3,3 --json-out m.map
# Every file a config makes a command read (engine/plan/files_read.h), however spelled: a map, its
# .scen, a YAML map and the image it names.
mkdir maps
tiny_map >maps/a.map
printf 'version 1\n0\ta.map\t4\t4\t0\t0\t3\t3\t4.24264069\n' >maps/a.map.scen
{ printf 'P5\n4 4\n255\n'; printf '\376%.0s' $(seq 16); } >maps/f.pgm
printf 'image: f.pgm\nresolution: 0.05\norigin: [0.0, 0.0, 0.0]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n' >maps/f.yaml
files_config() {  # $1 = report path
  cat <<JSON
{"name": "read", "seed": 3, "maps_per_cell": 1, "planners": ["astar"], "report": "$1",
 "generators": [{"name": "movingai", "params": {"files": ["maps/a.map"], "queries": "scen"}},
                {"name": "image", "params": {"files": ["maps/f.yaml"]}}]}
JSON
}
files_config mr.json >mc.json
ln maps/f.pgm hard.pgm
sums() { md5sum maps/* hard.pgm; }
before_maps=$(sums)
refused "--out a map file" '--out "maps/a.map": is the map file' "$bin" run mc.json --out maps/a.map --quiet
refused "--runs-out a .scen" '--runs-out "maps/a.map.scen": is the scenario file of .*a.map' \
  "$bin" run mc.json --runs-out maps/a.map.scen --quiet
refused "--out a YAML map's image, hard-linked" '--out "hard.pgm": is the occupancy image named by .*f.yaml' \
  "$bin" run mc.json --out hard.pgm --quiet
files_config maps/f.yaml >mv.json
refused "validate: a report onto a YAML map" 'report "maps/f.yaml": is the map file' "$bin" validate mv.json
refused "merge --out a map of its config" '--out "maps/a.map.scen": is the scenario file' \
  "$bin" merge j.jsonl --config mc.json --out maps/a.map.scen
refused "export --sqlite a map of its config" '--sqlite "hard.pgm": is the occupancy image' \
  "$bin" export j.jsonl --config mc.json --sqlite hard.pgm
[ "$before_maps" = "$(sums)" ] && ok "map files intact" || bad "a map file changed"
"$bin" run mc.json --out mr.json --quiet && ok "the map config runs" || bad "the map config (exit $?)"

cmp -s c.json c.orig && cmp -s j.jsonl j.orig && ok "config and journal intact" ||
  bad "config or journal changed"
"$bin" run c.json --out r.json --resume ./j.jsonl --runs-out j.jsonl --quiet &&
  ok "--runs-out naming the resumed journal however spelled is that journal" ||
  bad "--resume ./j.jsonl --runs-out j.jsonl refused"

# Class 2: a failed journal write stops the sweep (exit 1), names the journal and the OS error;
# the report is written incomplete; a resume completes it. The file-size limit (KiB) leaves room
# for the report (about 20 KiB) but not for the journal of 200 runs (about 160 KiB).
config big.report.json 100 >big.json
(ulimit -f 48 && exec "$bin" run big.json --threads 2 --runs-out big.jsonl --quiet) 2>err.txt
code=$?
if [ $code -ne 1 ] || ! grep -q 'journal "big.jsonl": write failed.*File too large.*--resume big.jsonl' err.txt; then
  bad "journal write failure: exit $code ($(head -c 300 err.txt))"
elif ! $py -c 'import json, sys; sys.exit(1 if json.load(open("big.report.json"))["complete"] else 0)'; then
  bad "journal write failure: no report marked incomplete ($(head -c 300 err.txt))"
else
  ok "journal write failure: exit 1, journal and OS error named, report incomplete"
fi
(ulimit -f 48 && exec "$bin" run big.json --threads 2 --resume big.jsonl --quiet) 2>err.txt
code=$?
[ $code -eq 1 ] && grep -q 'journal "big.jsonl": write failed.*File too large' err.txt &&
  ok "a resume on a full disk fails too (exit 1, named)" ||
  bad "a resume on a full disk: exit $code ($(head -c 300 err.txt))"
"$bin" run big.json --threads 2 --resume big.jsonl --quiet &&
  $py -c '
import json, sys
r = json.load(open("big.report.json"))
sys.exit(0 if r["complete"] else 1)' && $py "$journal_check" big.jsonl 200 >/dev/null &&
  ok "resume after the failure: complete, every run exactly once" ||
  bad "resume after the journal failure"

# Class 7: journal versions (and damaged records), each named by file and line, exit 2.
sed '1s/"journal_version":2/"journal_version":3/' j.orig >v3.jsonl
refused "resume refuses a foreign journal version" \
  'v3.jsonl:1: not a record .*journal_version 3; this agvbench reads tool "agvbench", journal_version 2' \
  "$bin" run c.json --out r4.json --resume v3.jsonl --quiet
sed '1s/"metrics":\["path_length"/"metrics":["path_len"/' j.orig >renamed.jsonl
refused "resume refuses a journal of an engine with other metric names" \
  'renamed.jsonl:1: header.s metric order does not start with .*written by an agvbench that measures other metrics' \
  "$bin" run c.json --out r6.json --resume renamed.jsonl --quiet
sed '1s/"tool":"agvbench","journal_version":2,//' j.orig >v0.jsonl
refused "merge refuses a journal without a version" \
  'v0.jsonl:1: not a record .*tool \(none\), journal_version \(none\)' \
  "$bin" merge v0.jsonl --config c.json --out r5.json
sed '3s/"metrics":\[[^],]*,/"metrics":[/' j.orig >short.jsonl
refused "merge refuses a run record whose values do not match its mask" \
  'short.jsonl:3: "metrics" holds fewer values than its mask names' \
  "$bin" merge short.jsonl --config c.json --out r7.json
sed '2s/"cell":0/"cell":99/' j.orig >cell.jsonl
refused "export refuses a map record of a cell the header lacks" \
  'cell.jsonl:2: "cell" 99 is not an index of the header' \
  "$bin" export cell.jsonl --config c.json --sqlite r8.db

# Class 9: names that are not UTF-8 are written (escaped), not refused after the work.
name=$(printf 'caf\xe9.map')
cp m.map "$name"
printf 'version 1\n0\t%s\t4\t4\t0\t0\t3\t3\t4.24264069\n' "$name" >m.scen
"$bin" plan --map "$name" --start 0,0 --goal 3,3 --json >plan.out 2>err.txt &&
  $py -c 'import json; d=json.load(open("plan.out", encoding="utf-8")); assert d["map"]["file"] == "caf\ufffd.map" and d["runs"][0]["outcome"] == "success"' &&
  ok "plan --json with a file name that is not UTF-8" ||
  bad "plan --json with a file name that is not UTF-8 ($(head -c 300 err.txt))"
"$bin" scen "$name" m.scen --json >scen.out 2>err.txt &&
  $py -c 'import json; d=json.load(open("scen.out", encoding="utf-8")); assert d["map"] == "caf\ufffd.map" and d["mismatches"] == 0' &&
  ok "scen --json with a file name that is not UTF-8" ||
  bad "scen --json with a file name that is not UTF-8 ($(head -c 300 err.txt))"
"$bin" plan --map "$name" --start 0,0 --goal 3,3 --json-out p.json --no-ascii >/dev/null 2>err.txt &&
  $py -c 'import json; json.load(open("p.json", encoding="utf-8"))' &&
  ok "plan --json-out with a file name that is not UTF-8" ||
  bad "plan --json-out with a file name that is not UTF-8 ($(head -c 300 err.txt))"

# Issue 28, class 7: a config, a map source's files and the folder they are in, with names that
# are not UTF-8, run (a cell named after such a file says \xNN for the odd bytes), in process and
# under --isolate alike, and resume; never the JSON library's exception.
odd=$(printf 'd\xe9j\xe0')
mkdir -p "$odd/maps"
tiny_map >"$odd/maps/$(printf 'caf\xe9.map')"
tiny_map >"$odd/maps/plain.map"
cat >"$odd/$(printf 'c\xe9.json')" <<JSON
{"name": "odd", "seed": 3, "maps_per_cell": 2, "planners": ["astar"], "report": "odd.json",
 "generators": [{"name": "movingai", "params": {"files": ["maps/*.map"]}}],
 "map": {"endpoints": "random", "min_distance": 1}}
JSON
"$bin" run "$odd/$(printf 'c\xe9.json')" --out odd.json --runs-out odd.jsonl --quiet 2>err.txt &&
  $py -c '
import json
r = json.load(open("odd.json", encoding="utf-8"))
cells = [c["cell"] for c in r["cells"]]
assert cells == ["movingai/caf\\xe9.map", "movingai/plain.map"] and r["complete"], cells
assert sum(1 for l in open("odd.jsonl", encoding="utf-8") if "\"planner\":" in l) == 4' &&
  ok "a config and map files named in bytes that are not UTF-8 run" ||
  bad "names that are not UTF-8: $(head -c 300 err.txt)"
"$bin" run "$odd/$(printf 'c\xe9.json')" "${isolate[@]}" --out odd_iso.json --quiet 2>err.txt &&
  $py "$src_dir/slurm/same_report.py" odd.json odd_iso.json >/dev/null &&
  ok "... and under --isolate, the same report" ||
  bad "--isolate with names that are not UTF-8: $(head -c 300 err.txt)"
head -n 3 odd.jsonl >odd_part.jsonl
"$bin" run "$odd/$(printf 'c\xe9.json')" --out odd_resumed.json --resume odd_part.jsonl --quiet 2>err.txt &&
  $py "$src_dir/slurm/same_report.py" odd.json odd_resumed.json >/dev/null &&
  ok "... and a resume of its journal completes to the same report" ||
  bad "resume with names that are not UTF-8: $(head -c 300 err.txt)"
"$bin" validate "$odd/$(printf 'c\xe9.json')" >/dev/null 2>err.txt && ok "... and validate" ||
  bad "validate with names that are not UTF-8: $(head -c 300 err.txt)"

# Issue 28, class 11: a NUL byte in a path the config gives cannot name the file meant, a file's
# binary bytes are not echoed raw into a message.
config 'nul\u0000.json' >nul.json
refused 'a NUL byte in "report"' 'report: "nul\\u0000.json" holds a NUL character' "$bin" run nul.json --quiet
config r.json | sed 's#"report"#"runs": "nul\\u0000.jsonl", "report"#' >nul.json
refused 'a NUL byte in "runs"' 'runs: "nul\\u0000.jsonl" holds a NUL character' "$bin" run nul.json --quiet
rm -f nul.json
{ printf 'type octile\nheight \033[31m\377\376\001\n'; } >bin.map
"$bin" plan --map bin.map --start 0,0 --goal 1,1 >out.txt 2>err.txt
code=$?
if [ $code -eq 2 ] && ! LC_ALL=C grep -q "$(printf '[\033\001\377]')" err.txt &&
  grep -qF "height '\x1b[31m\xff\xfe\x01' is not a whole number" err.txt; then
  ok "binary bytes of a map escaped in its message: $(head -c 160 err.txt)"
else
  bad "binary map: exit $code, $(od -c err.txt | head -5)"
fi

# A report temporary left by a killed writer is removed at the next write of that report.
sh -c 'exit 0' & dead=$!
wait $dead
printf '{' >"r.json.tmp.$dead"
printf '{' >"r.json.tmp.$$"  # this shell is alive: another writer's, kept
"$bin" run c.json --out r.json --quiet || bad "run (exit $?)"
[ ! -e "r.json.tmp.$dead" ] && [ -e "r.json.tmp.$$" ] &&
  ok "stale report temporary removed, a live writer's kept" ||
  bad "report temporaries: $(ls r.json.tmp.* 2>/dev/null)"

finish test_files
