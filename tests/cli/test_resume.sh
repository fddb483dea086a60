#!/usr/bin/env bash
# Sweeps that survive (issue 8): SIGINT at about 10%, 50% and 90% of a sweep, then --resume:
# the final report equals the uninterrupted one (non-timing fields) and no run appears twice in
# the journal. Then SIGKILL at random moments, report writing included: the report on disk
# always parses. Usage: test_resume.sh AGVBENCH SOURCE_DIR
set -u
bin=$1
src=$2
same=$src/slurm/same_report.py
source "$(dirname "$0")/lib.sh"

cat >config.json <<'JSON'
{"name": "resume-test", "seed": 11, "generators": ["uniform", "rooms"], "sizes": [48, 96],
 "densities": [0.1, 0.3], "maps_per_cell": 75, "planners": ["astar", "dijkstra"],
 "report": "unused.json"}
JSON
total=$((2 * 2 * 2 * 75 * 2))

"$bin" run config.json --threads 2 --out full.json --quiet || { bad "uninterrupted run"; exit 1; }

for pct in 10 50 90; do
  rm -f j.jsonl part.json final.json
  "$bin" run config.json --threads 2 --out part.json --runs-out j.jsonl --quiet &
  pid=$!
  want=$((total * pct / 100))
  for _ in $(seq 1 600); do
    n=$(grep -c '"planner":' j.jsonl 2>/dev/null)
    n=${n:-0}
    [ "$n" -ge "$want" ] && break
    kill -0 $pid 2>/dev/null || break
    sleep 0.01
  done
  kill -INT $pid 2>/dev/null
  wait $pid
  code=$?
  done_lines=$(grep -c '"planner":' j.jsonl)
  if [ $code -eq 130 ]; then
    $py -c "import json,sys; r=json.load(open('part.json')); sys.exit(0 if r['complete'] is False else 1)" \
      && ok "SIGINT at ~$pct% ($done_lines/$total runs): exit 130, report marked incomplete" \
      || bad "SIGINT at ~$pct%: report not marked incomplete"
  elif [ $code -eq 0 ]; then
    echo "note: the sweep finished before SIGINT at ~$pct% arrived"
  else
    bad "SIGINT at ~$pct%: exit $code"
  fi
  "$bin" run config.json --threads 2 --out final.json --resume j.jsonl --quiet
  [ $? -eq 0 ] || bad "resume after ~$pct%: non-zero exit"
  $py "$same" full.json final.json && ok "resume after ~$pct%: report equals the uninterrupted one" \
    || bad "resume after ~$pct%: report differs"
  $py "$journal_check" j.jsonl $total && ok "resume after ~$pct%: every run exactly once" \
    || bad "resume after ~$pct%: runs missing or repeated"
done

# A torn last line (a kill mid-write) is tolerated and cut before appending: the first 100 lines
# (the header, map records and runs) and 50 bytes of a later one.
rm -f j.jsonl
"$bin" run config.json --threads 2 --out part.json --runs-out j.jsonl --quiet
head -c -40 j.jsonl >t.jsonl && head -n 100 t.jsonl >j2.jsonl && tail -c 70 t.jsonl | head -c 50 >>j2.jsonl
"$bin" run config.json --threads 2 --out final.json --resume j2.jsonl --quiet \
  && $py "$same" full.json final.json && $py "$journal_check" j2.jsonl $total \
  && ok "torn last line tolerated" || bad "torn last line"

# A gzip journal (--runs-out J.jsonl.gz, a member per write): SIGKILL part way, then --resume
# cuts the torn member and appends; the report equals the uninterrupted one, every run is in the
# journal once, and gzip reads the whole file.
for pct in 30 70; do
  rm -f j.jsonl.gz final.json
  "$bin" run config.json --threads 2 --out part.json --runs-out j.jsonl.gz --quiet &
  pid=$!
  want=$((total * pct / 100))
  for _ in $(seq 1 600); do
    n=$(gzip -dc j.jsonl.gz 2>/dev/null | grep -c '"planner":')
    [ "${n:-0}" -ge "$want" ] && break
    kill -0 $pid 2>/dev/null || break
    sleep 0.01
  done
  kill -KILL $pid 2>/dev/null
  wait $pid 2>/dev/null
  "$bin" run config.json --threads 2 --out final.json --resume j.jsonl.gz --quiet \
    && $py "$same" full.json final.json && $py "$journal_check" j.jsonl.gz $total \
    && gzip -t j.jsonl.gz \
    && ok "gzip journal: SIGKILL at ~$pct%, resumed: the uninterrupted report, every run once" \
    || bad "gzip journal: SIGKILL at ~$pct%, resumed"
done
# A member cut in half by hand (a kill mid-write) is cut before appending.
rm -f j.jsonl.gz
"$bin" run config.json --threads 2 --out part.json --runs-out j.jsonl.gz --quiet
head -c $(($(stat -c %s j.jsonl.gz) / 2)) j.jsonl.gz >j2.jsonl.gz
"$bin" run config.json --threads 2 --out final.json --resume j2.jsonl.gz --quiet \
  && $py "$same" full.json final.json && $py "$journal_check" j2.jsonl.gz $total && gzip -t j2.jsonl.gz \
  && ok "gzip journal: torn member cut, resumed" || bad "gzip journal: torn member"

# A journal of another config is refused.
sed 's/"seed": 11/"seed": 12/' config.json >other.json
"$bin" run other.json --out o.json --resume j.jsonl --quiet 2>err.txt
[ $? -eq 2 ] && grep -q "different config" err.txt && [ ! -e o.json ] \
  && ok "journal of another config refused: $(head -c 150 err.txt)" || bad "foreign journal accepted"

# SIGKILL at random moments: the report is the old one or the new one, never torn.
cat >small.json <<'JSON'
{"name": "kill-test", "seed": 3, "sizes": [64], "densities": [0.2], "maps_per_cell": 200,
 "planners": ["astar", "dijkstra"], "report": "unused.json"}
JSON
echo '{"old": true}' >r.json
torn=0
trials=40
for i in $(seq 1 $trials); do
  "$bin" run small.json --threads 2 --out r.json --quiet &
  pid=$!
  sleep "0.$((RANDOM % 40))"
  kill -KILL $pid 2>/dev/null
  wait $pid 2>/dev/null
  $py -c "import json; json.load(open('r.json'))" 2>/dev/null || torn=$((torn + 1))
done
[ $torn -eq 0 ] && ok "SIGKILL x$trials: the report always parses" || bad "SIGKILL: $torn torn reports"

finish test_resume
