# Shared by the CLI test scripts (sourced): a scratch folder to work in, removed on exit, and
# pass/fail bookkeeping. `finish NAME` prints the tally and returns non-zero on any failure.
py=/usr/bin/python3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
pass=0
fail=0
ok() { echo "ok   $1"; pass=$((pass + 1)); }
bad() { echo "FAIL $1"; fail=$((fail + 1)); }
finish() {
  echo "$1: $pass passed, $fail failed"
  [ "$fail" -eq 0 ]
}
