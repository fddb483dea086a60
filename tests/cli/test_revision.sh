#!/usr/bin/env bash
# The git revision is read at build time (engine/git_revision.cmake): the revision a report names
# is the tree the binary was built from, HEAD's 12-digit short hash, "-dirty" appended when a
# tracked file differs from HEAD. The script itself: "unknown" outside a git checkout (or
# inside some other checkout), the hash in a fresh repository, "-dirty" after an edit, and the
# header left untouched (same mtime) when nothing changed, so an unchanged tree relinks
# nothing. Exit 77 (skipped) when git is missing. Usage: test_revision.sh AGVBENCH SOURCE_DIR CMAKE
set -u
bin=$1
src=$2
cmake=$3
script=$src/engine/git_revision.cmake
source "$(dirname "$0")/lib.sh"

command -v git >/dev/null || { echo "skipped: git is not installed"; exit 77; }

revision_of() {  # SOURCE_DIR OUTPUT: runs the script, prints the revision the header holds
  "$cmake" -DSOURCE_DIR="$1" -DGIT_EXECUTABLE="$(command -v git)" -DOUTPUT="$2" -P "$script" &&
    sed -n 's/.*kGitRevision = "\(.*\)";/\1/p' "$2"
}

# The binary under test, against the checkout it was built from.
top=$(git -C "$src" rev-parse --show-toplevel 2>/dev/null)
if [ -n "$top" ] && [ "$(realpath "$top")" = "$(realpath "$src")" ]; then
  want=$(git -C "$src" rev-parse --short=12 HEAD)
  [ -n "$(git -C "$src" --no-optional-locks status --porcelain --untracked-files=no)" ] &&
    want="$want-dirty"
  cat >config.json <<'JSON'
{"name": "revision-test", "sizes": [12], "densities": [0.1], "maps_per_cell": 1,
 "planners": ["astar"], "report": "unused.json"}
JSON
  "$bin" run config.json --threads 1 --out r.json --quiet || bad "agvbench run exit $?"
  got=$($py -c 'import json; print(json.load(open("r.json"))["environment"]["git_revision"])')
  [ "$got" = "$want" ] && ok "the report names the tree's revision $want" ||
    bad "the report names $got, the tree is $want (built before the last commit or edit?)"
else
  echo "note: $src is not a git checkout; the binary's revision is not checked"
fi

# The script on its own, in scratch trees.
mkdir plain
[ "$(revision_of plain plain.h)" = unknown ] && ok "outside a git checkout: unknown" ||
  bad "outside a git checkout: $(revision_of plain plain.h)"

git init -q repo
echo one >repo/file.txt
git -C repo add file.txt
git -C repo -c user.name=test -c user.email=test@example.com commit -q -m one
head=$(git -C repo rev-parse --short=12 HEAD)
[ "$(revision_of repo repo.h)" = "$head" ] && ok "clean checkout: $head" ||
  bad "clean checkout: $(revision_of repo repo.h), want $head"

touch -d '2000-01-01' repo.h
before=$(stat -c %Y repo.h)
revision_of repo repo.h >/dev/null
[ "$(stat -c %Y repo.h)" = "$before" ] && ok "unchanged revision: header not rewritten" ||
  bad "unchanged revision: header rewritten"

echo untracked >repo/new.txt
[ "$(revision_of repo repo.h)" = "$head" ] && ok "an untracked file is not dirty" ||
  bad "an untracked file: $(revision_of repo repo.h)"
echo two >repo/file.txt
[ "$(revision_of repo repo.h)" = "$head-dirty" ] && ok "edited tracked file: $head-dirty" ||
  bad "edited tracked file: $(revision_of repo repo.h), want $head-dirty"

mkdir repo/unpacked
[ "$(revision_of repo/unpacked unpacked.h)" = unknown ] &&
  ok "a tree inside another checkout: unknown" ||
  bad "a tree inside another checkout: $(revision_of repo/unpacked unpacked.h)"

finish test_revision
