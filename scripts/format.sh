#!/usr/bin/env bash
# clang-format over every tracked C++ file, with the committed .clang-format (Debian 12's
# clang-format 14; another version may format differently, so CI installs the same package).
# Usage: scripts/format.sh          formats the tree in place
#        scripts/format.sh --check  lists the files that are not clean; exit 1 if any (CI)
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/apt_need.sh clang-format git
mapfile -t files < <(git ls-files '*.cpp' '*.h')
if [ "${1:-}" = --check ]; then
  # Batches of 16 files, one clang-format per core; each names every unclean line it finds
  # ("FILE:LINE:COL: error: code should be clang-formatted").
  rc=0
  out=$(printf '%s\0' "${files[@]}" |
    xargs -0 -n 16 -P "$(nproc 2>/dev/null || echo 2)" clang-format --dry-run --Werror 2>&1 >/dev/null) || rc=$?
  mapfile -t unclean < <(sed -n 's/^\(.*\):[0-9]*:[0-9]*: error: .*/\1/p' <<<"$out" | sort -u)
  if ((rc != 0 && ${#unclean[@]} == 0)); then
    printf '%s\n' "$out" >&2
    echo "format: clang-format failed (exit $rc)" >&2
    exit 1
  fi
  if ((${#unclean[@]})); then
    printf 'format: not clean under .clang-format: %s\n' "${unclean[@]}" >&2
    echo "format: ${#unclean[@]} of ${#files[@]} files; run scripts/format.sh" >&2
    exit 1
  fi
  echo "format: all ${#files[@]} C++ files clean"
elif (($#)); then
  echo "usage: $0 [--check]" >&2
  exit 2
else
  clang-format -i "${files[@]}"
  echo "format: formatted ${#files[@]} files"
fi
