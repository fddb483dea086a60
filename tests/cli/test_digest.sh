#!/usr/bin/env bash
# `agvbench digest`: one line per report in sha256sum's layout; the digest ignores timing and
# environment, moves with any other value, is the same on 1 and 2 threads, and bad input is exit 2
# with no line printed. Usage: test_digest.sh AGVBENCH SOURCE_DIR
set -u
bin=$1
src=$2
source "$(dirname "$0")/lib.sh"
digest_of() { "$bin" digest "$1" | cut -d' ' -f1; }
edit() {  # IN OUT PYTHON-STATEMENT (on r, the report)
  $py -c "import json,sys; r=json.load(open(sys.argv[1])); $3; json.dump(r, open(sys.argv[2],'w'))" "$1" "$2"
}

# The golden registry config (every deterministic planner); in a sanitized build (AGV_SANITIZED,
# tests/CMakeLists.txt) one map per cell instead of four, the same code at a quarter of the cost.
cfg=$src/tests/golden/registry.json
if [ "${AGV_SANITIZED:-0}" = 1 ]; then
  cfg=$PWD/registry1.json
  $py -c "import json,sys; c=json.load(open(sys.argv[1])); c['maps_per_cell']=1; json.dump(c, open(sys.argv[2],'w'))" "$src/tests/golden/registry.json" "$cfg"
fi
"$bin" run "$cfg" --threads 1 --out one.json --quiet || bad "run, 1 thread"
"$bin" run "$cfg" --threads 2 --out two.json --quiet || bad "run, 2 threads"
"$bin" digest one.json two.json >out.txt
if [ "$(wc -l <out.txt)" = 2 ] && grep -Eq '^[0-9a-f]{64}  one\.json$' out.txt &&
  grep -Eq '^[0-9a-f]{64}  two\.json$' out.txt; then ok "one line per report"; else bad "layout"; cat out.txt; fi
a=$(digest_of one.json)
[ ${#a} = 64 ] || bad "no digest of one.json"
[ "$a" = "$(digest_of two.json)" ] && ok "same digest on 1 and 2 threads" || bad "threads change the digest"
edit one.json timing.json "r['timing']['wall_ns'] = 1; r['environment'] = {'host': 'elsewhere'}; r['cells'][0]['planners'][0]['timing'] = {}"
[ "$a" = "$(digest_of timing.json)" ] && ok "timing and environment do not count" || bad "timing counts"
edit one.json metric.json "p = r['cells'][0]['planners'][0]; p['successes'] = p['successes'] - 1"
[ "$a" != "$(digest_of metric.json)" ] && ok "a changed count changes it" || bad "a changed count is unseen"
edit one.json bits.json "
def nudge(v):
    if isinstance(v, float) and v not in (0.0,):
        import math; return math.nextafter(v, math.inf), True
    if isinstance(v, dict):
        for k in v:
            if k in ('timing', 'environment'): continue
            v[k], done = nudge(v[k])
            if done: return v, True
    if isinstance(v, list):
        for i in range(len(v)):
            v[i], done = nudge(v[i])
            if done: return v, True
    return v, False
nudge(r['cells'])"
[ "$a" != "$(digest_of bits.json)" ] && ok "one float one ulp away changes it" || bad "a last-bit change is unseen"

echo '{"tool": "agvbench", "config": {}' >broken.json
echo '{"tool": "other", "config": {}, "cells": []}' >other.json
for f in broken.json other.json missing.json; do
  "$bin" digest one.json "$f" >out.txt 2>err.txt
  rc=$?
  if [ "$rc" = 2 ] && [ ! -s out.txt ] && [ "$(wc -l <err.txt)" = 1 ] && grep -q "$f" err.txt; then
    ok "$f: exit 2, one line naming it, nothing printed"
  else
    bad "$f: exit $rc"; cat out.txt err.txt
  fi
done
finish test_digest
