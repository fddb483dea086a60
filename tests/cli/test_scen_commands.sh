#!/usr/bin/env bash
# plan and scen on MovingAI benchmark maps, as the README shows them: the first queries of two
# published scenario files (the optima of every query are the test suite's MovingAiScenarios;
# this script also runs under the sanitizers). Needs the MovingAI sets (docs/TESTING.md "Test
# data"): exits 77, which ctest shows as skipped, without them.
# Usage: test_scen_commands.sh AGVBENCH SOURCE_DIR
set -u
bin=$1
src=$2
source "$(dirname "$0")/lib.sh"
maps=$(movingai_sets "$src")
case $? in
  0) ;;
  1)
    echo "skipped: needs the MovingAI sets: set AGVBENCH_MOVINGAI_DIR or put them in ../shared/maps beside the checkout"
    exit 77
    ;;
  *) exit 1 ;;
esac
check "plan on a MovingAI map" sh -c "'$bin' plan --map '$maps/random512-10-0.map' --start 174,10 --goal 172,9 --param corner_rule=no_corner_cut --no-ascii | grep -q 'path_length = 2.414'"
head -n 61 "$maps/random512-10-0.map.scen" >random60.scen
head -n 31 "$maps/maze512-1-0.map.scen" >maze30.scen
check "scen: random512-10-0 optimal under astar" sh -c "'$bin' scen '$maps/random512-10-0.map' random60.scen | grep -q ' 0 mismatches'"
check "scen --json: dijkstra on maze512-1-0" sh -c "'$bin' scen '$maps/maze512-1-0.map' maze30.scen --planner dijkstra --json | $py -c 'import json,sys; r=json.load(sys.stdin); assert r[\"mismatches\"]==0 and r[\"queries\"]==30 and \"median_query_ns\" in r[\"timing\"]'"
finish test_scen_commands
