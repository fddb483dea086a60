#!/usr/bin/env bash
# The dependency rule of docs/ARCHITECTURE.md, checked on the includes: core/ includes nothing of
# ours; generators/ and algos/ stand on core/ only and never include each other (nor engine/);
# nothing below the command line includes cli/, and python/ (the second front-end) drives the
# engine without it;
# at the top of algos/ sit only the planner interface, what a planner declares and the registry;
# engine/ is in rooms, each including only the rooms before it (docs/ARCHITECTURE.md "Engine
# rooms"): system, judge, plan, outputs, sweep; no source lies outside a room.
# Usage: check_dependencies.sh SOURCE_DIR
set -uo pipefail
cd "${1:?usage: $0 SOURCE_DIR}"
fail=0
forbid() {  # FOLDER PATTERN WHY
  local hits
  hits=$(grep -rnE "#include \"($2)/" --include='*.h' --include='*.cpp' "$1" || true)
  if [ -n "$hits" ]; then
    echo "FAIL $1/ must not include $2/ ($3):"
    echo "$hits"
    fail=1
  else
    echo "ok   $1/ includes no $2/"
  fi
}
forbid core 'generators|algos|engine|cli' 'core knows no map source, no planner, no sweep'
forbid generators 'algos|engine|cli' 'a generator knows no planner'
forbid algos 'generators|engine|cli' 'a planner sees a grid, never how it was made'
forbid engine 'cli|python' 'the command line is a front-end above the engine'
forbid python 'cli' 'the Python module is the second front-end: it drives the engine, not the CLI'
forbid cli 'python' 'the two front-ends stand side by side'
top=$(find algos -maxdepth 1 -name '*.cpp' -printf '%f\n' | sort | tr '\n' ' ')
if [ "$top" = "planner.cpp planner_info.cpp registry.cpp " ]; then
  echo "ok   algos/ top level holds only the interface, the planner declaration and the registry"
else
  echo "FAIL algos/ top level holds: $top(expected planner.cpp planner_info.cpp registry.cpp)"
  fail=1
fi
rooms=(system judge plan outputs sweep)
for i in "${!rooms[@]}"; do
  later=$(IFS='|'; echo "${rooms[*]:i+1}")
  if [ -n "$later" ]; then
    forbid "engine/${rooms[$i]}" "engine/($later)" 'a room stands only on the rooms before it'
  fi
done
loose=$(find engine -maxdepth 1 \( -name '*.h' -o -name '*.cpp' \) -printf '%f ' | sort)
if [ -z "$loose" ]; then
  echo "ok   engine/ top level holds no source; every unit is in a room"
else
  echo "FAIL engine/ top level holds sources outside the rooms: $loose"
  fail=1
fi
unknown=$(find engine -mindepth 1 -maxdepth 1 -type d -printf '%f\n' | grep -vxE "$(IFS='|'; echo "${rooms[*]}")" || true)
if [ -n "$unknown" ]; then
  echo "FAIL engine/ has a folder that is not a room of the rule: $unknown"
  fail=1
fi
exit $fail
