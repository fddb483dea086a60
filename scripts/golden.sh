#!/usr/bin/env bash
# The golden digests (docs/TESTING.md "Golden digests"): the SHA-256 of the non-timing part of the
# reports of a few fixed configs (`agvbench digest`), kept in tests/golden/digests.txt. Results
# that change by accident change a digest, and the suite's golden_digests test fails.
#   scripts/golden.sh [AGVBENCH]           regenerate tests/golden/digests.txt (a change of results
#                                          on purpose: commit it on its own, saying why)
#   scripts/golden.sh --check [AGVBENCH]   compare with it (exit 1 naming each config that moved)
# AGVBENCH defaults to build/agvbench. Reports go to $AGVBENCH_GOLDEN_DIR when set (kept, for
# `agvbench compare` against an older build's), else to a temporary folder (kept on a mismatch).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
check=0
if [ "${1:-}" = --check ]; then
  check=1
  shift
fi
agvbench=${1:-$root/build/agvbench}
digests=$root/tests/golden/digests.txt
# The configs, relative to the repository root. registry.json runs every deterministic planner of
# the registry; tests/golden/check_registry.py keeps it so.
configs=(configs/quick.json tests/golden/registry.json)

[ -x "$agvbench" ] || { echo "golden: no agvbench at $agvbench (build it first)" >&2; exit 2; }
/usr/bin/python3 "$root/tests/golden/check_registry.py" "$agvbench" "$root/tests/golden/registry.json"
out=${AGVBENCH_GOLDEN_DIR:-$(mktemp -d)}
mkdir -p "$out"
keep=${AGVBENCH_GOLDEN_DIR:+1}
new=$out/digests.txt
: >"$new"
for c in "${configs[@]}"; do
  report=$out/$(basename "$c" .json).json
  # Any thread count gives the same digest (the sweep's determinism); two use both cores.
  "$agvbench" run "$root/$c" --threads 2 --out "$report" --quiet
  echo "$("$agvbench" digest "$report" | cut -d' ' -f1)  $c" >>"$new"
done

if ((check == 0)); then
  tmp=$digests.tmp.$$
  cp "$new" "$tmp" && mv "$tmp" "$digests"
  cat "$digests"
  [ -n "$keep" ] || rm -rf "$out"
  exit 0
fi
rc=0
while read -r want c; do
  got=$(awk -v c="$c" '$2 == c {print $1}' "$new")
  if [ "$got" = "$want" ]; then
    echo "golden: $c: $got"
  else
    echo "golden: $c: results changed: digest ${got:-missing}, expected $want" >&2
    rc=1
  fi
done <"$digests"
if [ "$(wc -l <"$new")" != "$(wc -l <"$digests")" ]; then
  echo "golden: $digests lists $(wc -l <"$digests") configs, the script runs ${#configs[@]}" >&2
  rc=1
fi
if ((rc)); then
  echo "golden: the reports are in $out; on purpose? compare them with the last build's" \
    "(agvbench compare), run scripts/golden.sh and commit tests/golden/digests.txt on its own" >&2
elif [ -z "$keep" ]; then
  rm -rf "$out"
fi
exit "$rc"
