#!/usr/bin/env bash
# The line-of-sight kernel's instruction-set levels (core/simd_path.h): AGVBENCH_SIMD forces one;
# the quick sweep's report has the golden digest at every level this CPU runs (a level's verdicts
# are the baseline's, so are the results); a level the CPU lacks and an unknown name are bad input
# (exit 2, naming AGVBENCH_SIMD). Usage: test_simd_levels.sh AGVBENCH SOURCE_DIR
set -u
bin=$1
src=$2
source "$(dirname "$0")/lib.sh"
golden=$(awk '$2 == "configs/quick.json" {print $1}' "$src/tests/golden/digests.txt")
[ -n "$golden" ] || { echo "no golden digest of configs/quick.json"; exit 1; }

ran=()
for level in baseline avx2 avx512; do
  if AGVBENCH_SIMD=$level "$bin" run "$src/configs/quick.json" --threads 2 --out "q-$level.json" \
    --quiet >out.txt 2>err.txt; then
    ran+=("$level")
    simd=$($py -c 'import json,sys; print(json.load(open(sys.argv[1]))["environment"]["simd"])' "q-$level.json")
    [ "$simd" = "$level" ] && ok "$level: the report's environment says simd $level" ||
      bad "$level: the report's environment says simd '$simd'"
    digest=$("$bin" digest "q-$level.json" | cut -d' ' -f1)
    [ "$digest" = "$golden" ] && ok "$level: the quick sweep's golden digest" ||
      bad "$level: digest $digest, golden $golden"
  elif [ $? -eq 2 ] && grep -q "AGVBENCH_SIMD=$level: this \(CPU cannot run\|build has no\)" err.txt &&
    [ ! -e "q-$level.json" ]; then
    ok "$level: refused on this machine with one line, nothing written ($(head -c 120 err.txt))"
  else
    bad "$level: $(head -c 300 err.txt)"
  fi
done
[ "${ran[0]:-}" = baseline ] && ok "the baseline level runs (levels run here: ${ran[*]})" ||
  bad "the baseline level did not run"

AGVBENCH_SIMD=avx3 "$bin" validate "$src/configs/quick.json" >out.txt 2>err.txt
rc=$?
[ $rc -eq 2 ] && grep -q "AGVBENCH_SIMD=avx3 is not one of baseline, avx2, avx512, auto" err.txt &&
  [ "$(wc -l <err.txt)" -eq 1 ] && ok "an unknown level: exit 2 and one line" ||
  bad "an unknown level: exit $rc, $(cat err.txt)"
(cd "$src" && AGVBENCH_SIMD=auto "$bin" validate configs/quick.json) >out.txt 2>err.txt &&
  ok "auto picks the best level" || bad "auto: $(cat err.txt)"
finish test_simd_levels
