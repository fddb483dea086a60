# Shared by the report test scripts (sourced, after each sets `py`): a scratch folder `$work`,
# removed on exit, and pass/fail bookkeeping; `finish` prints the tally and returns non-zero on
# any failure. Unlike tests/cli/lib.sh it does not change folder: the scripts name their paths.
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
pass=0
fail=0
ok() { echo "ok   $1"; pass=$((pass + 1)); }
bad() { echo "FAIL $1"; fail=$((fail + 1)); }
finish() {
  echo "$pass passed, $fail failed"
  [ "$fail" -eq 0 ]
}
