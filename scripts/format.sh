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
  unclean=()
  for f in "${files[@]}"; do
    clang-format --dry-run --Werror "$f" >/dev/null 2>&1 || unclean+=("$f")
  done
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
