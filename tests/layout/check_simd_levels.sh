#!/usr/bin/env bash
# A kernel's instruction-set level copies (core/simd_target.h: the line of sight, DWA's rollouts)
# must not hand a level's instructions to code outside the kernel. The danger is a weak function
# (a header's inline function or template kept out of line): the linker keeps one copy for every
# caller, and were it compiled with a level's features, a CPU without them would die of an illegal
# instruction. So every weak function a level object defines must be in the baseline object too,
# instruction for instruction (addresses and symbolic annotations aside): compiled for the build's
# own target, as core/simd_target.h intends.
# Usage: check_simd_levels.sh BASELINE_OBJECT LEVEL_OBJECT... [-- BASELINE_OBJECT LEVEL_OBJECT...]
set -u
fail=0
checked=0

code() {  # OBJECT SYMBOL: its instructions, without addresses, bytes and <symbol+offset> notes
  # The body alone: from its label to the first blank line (objdump then names every other
  # section of the object, whose names differ between the levels' namespaces).
  objdump -d --no-show-raw-insn --disassemble="$2" "$1" | sed -n '/>:$/,/^$/p' | tail -n +2 |
    sed -e 's/^ *[0-9a-f]*:\s*//' -e 's/ *<[^>]*>//g' -e 's/ *#.*$//'
}

check_group() {  # BASELINE LEVEL...
  local base=$1 o s
  shift
  for o in "$@"; do
    local bad=0
    for s in $(nm --defined-only "$o" | awk '$2 == "W" {print $3}'); do
      checked=$((checked + 1))
      if [ "$(code "$o" "$s")" != "$(code "$base" "$s")" ]; then
        echo "FAIL $o: weak function $(echo "$s" | c++filt) differs from the baseline's copy"
        bad=1
      fi
    done
    ((bad)) && fail=1 || echo "ok   $o: its weak functions are the baseline's"
  done
}

[ $# -ge 2 ] || { echo "FAIL give a baseline object and level objects"; exit 1; }
group=()
for a in "$@" --; do
  if [ "$a" = -- ]; then
    ((${#group[@]})) && check_group "${group[@]}"
    group=()
  else
    group+=("$a")
  fi
done
echo "check_simd_levels: $checked weak functions compared"
exit $fail
