#!/usr/bin/env bash
# Sanitizer builds: the test suite under ASan+UBSan (build-asan/, clang, which also holds the
# libFuzzer harnesses that scripts/fuzz.sh then runs: FUZZ_BUILD_DIR=build-asan), and a
# multi-threaded sweep plus the sweep determinism suite under TSan (build-tsan/). Any sanitizer
# report fails the run.
# The project's library packages come from scripts/setup.sh (CI runs it first).
#
# Usage: scripts/sanitize.sh [asan|tsan]...      (default: both)
# Env:   SANITIZE_JOBS (default nproc), CTEST_ARGS (extra ctest arguments, e.g. "-R Sweep"),
#        ASAN_CTEST_EXCLUDE (ctest -E regex of tests the ASan run skips; empty = none)
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
parts=("$@")
((${#parts[@]})) || parts=(asan tsan)
jobs=${SANITIZE_JOBS:-$(nproc 2>/dev/null || echo 2)}
scripts/apt_need.sh cmake ninja-build g++

# -O1 -g1: the optimisation the sanitizers' own docs suggest, and line tables only (file:line
# in every report's stack, no variable info): the build is the CI's longest stage, and full -g
# makes the sanitized objects twice as large for nothing a report prints.
configure() {  # DIR SANITIZERS [CMAKE ARGS...]
  cmake -S . -B "$1" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DAGVBENCH_SANITIZE="$2" \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
    -DAGVBENCH_BUILD_PERF=OFF -DAGVBENCH_NATIVE=OFF "${@:3}" >/dev/null
}

# TSan sees only the synchronisation of code it instrumented. Debian's libtbb is not, so every
# hand-over through TBB's scheduler (a task spawned, stolen, waited for) looks like a data race:
# on a stock libtbb, test_sweep gives 43 reports, in TBB's headers and in our parallel_for body
# alike, which no suppression could separate from real races. oneTBB's answer is to build
# libtbb itself with TSan (its CMake option TBB_SANITIZE=thread); this does that once, from
# Debian's source package of the installed libtbb-dev (same version, same headers), into
# build-tsan/tbb/ (about 1 minute), and build-tsan links against it.
tsan_tbb() {
  local dir=$root/build-tsan/tbb
  [ -e "$dir/install/lib/cmake/TBB/TBBConfig.cmake" ] && return 0
  scripts/apt_need.sh dpkg-dev xz-utils libtbb-dev
  local src ver codename
  src=$(dpkg-query -W -f='${source:Package}' libtbb-dev)
  ver=$(dpkg-query -W -f='${source:Version}' libtbb-dev)
  codename=$(. /etc/os-release && echo "$VERSION_CODENAME")
  rm -rf "$dir" && mkdir -p "$dir/apt/lists/partial" "$dir/apt/cache/archives/partial"
  # A private apt configuration: deb-src lines for the mirrors the machine's own apt sources
  # name (scripts/apt_source_lines.sh), without touching /etc/apt.
  scripts/apt_source_lines.sh "$codename" >"$dir/apt/sources.list"
  [ -s "$dir/apt/sources.list" ] ||
    { echo "sanitize: no Debian $codename suite in the machine's apt sources to fetch libtbb's source from" >&2; return 1; }
  local opts=(-o "Dir::Etc::SourceList=$dir/apt/sources.list" -o "Dir::Etc::SourceParts=$dir/apt/none"
    -o "Dir::State::Lists=$dir/apt/lists" -o "Dir::Cache=$dir/apt/cache" -o "APT::Sandbox::User=root"
    -o Acquire::Retries=3)
  apt-get "${opts[@]}" update -qq
  (cd "$dir" && apt-get "${opts[@]}" source -qq --download-only "$src=$ver" &&
    dpkg-source -x ./*.dsc src >/dev/null 2>&1)
  cmake -S "$dir/src" -B "$dir/build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DTBB_SANITIZE=thread -DTBB_STRICT=OFF -DTBB_TEST=OFF -DTBB_EXAMPLES=OFF -DTBBMALLOC_BUILD=OFF \
    -DTBB_DISABLE_HWLOC_AUTOMATIC_SEARCH=ON -DCMAKE_INSTALL_PREFIX="$dir/install" >/dev/null
  cmake --build "$dir/build" -j "$jobs" >/dev/null
  cmake --install "$dir/build" >/dev/null
  echo "sanitize: built libtbb $ver with TSan in $dir/install"
}

asan_exclude='MovingAiScenarios|\.FullSets|^ReferenceBounds\.|^Fusion\.ReachesTheGoalOnRandomSolvableMaps$|^HmaStar\.SoundOnPaperMapsAndPairedAgainstAStar$|^Sweep\.ReportIsIdenticalOnOneAndTwoThreads$|^Fusion\.AllThreeVariantsRunWithMovingAndUnknownObstacles$|^Fusion\.RunMetricsCoverTheUnknownCellsAndTakeTheSimulatedTime$|^Fusion\.LocalGoalsAreTheKeyNodesOrTheCurveSamples$|^FusionSweep\.ReportIsIdenticalOnOneAndTwoThreads$|^cli_resume_interrupt$|^plot_scripts$|^html_report$|^report_odd_labels$|^cli_plugin$|^Registry/PlannerContract\..*/ompl_(rrtstar|informed_rrtstar|bitstar|lazyprmstar)( |$)|^Registry/PlannerContract\.(DeadlineCutsEveryPhaseOfALongPlan|WaypointCountIsThatOfThePathReturned)/(fusion_[a-z]+_dwa|dwa)$|^Registry/PlannerContract\.(ReportsTheWorkCountersItDeclares|SameSeedSameResult)/fusion_(alt|kin)_dwa$'

seed_costs() {  # BUILD_DIR COST_FILE: ctest's cost data for a fresh build folder (long tests first)
  local data=$1/Testing/Temporary/CTestCostData.txt
  [ -s "$data" ] && return 0
  mkdir -p "$1/Testing/Temporary" && cp "$2" "$data"
}

for part in "${parts[@]}"; do
  start=$(date +%s)
  case $part in
    asan)
      # clang, and the fuzz harnesses in the same tree: one ASan+UBSan build serves both stages
      # (the harnesses' coverage instrumentation costs the suite little; a second sanitized tree
      # for them cost CI five minutes of compiling).
      scripts/apt_need.sh clang libclang-rt-14-dev
      configure build-asan address,undefined -DCMAKE_CXX_COMPILER=clang++ -DAGVBENCH_FUZZ=ON
      cmake --build build-asan -j "$jobs"
      echo "sanitize: asan build took $(( $(date +%s) - start )) s"
      # Left to the plain suite: tests labelled `long`, and by default (ASAN_CTEST_EXCLUDE
      # overrides) the few whose inputs are big, not their code: the MovingAI scenario suites
      # and every GoogleTest of the MovingAI sets (Suite.FullSets*: whole 512x512 benchmark maps;
      # the readers' own small maps and cli_scen_commands_FullSets' 90 queries run here), the
      # fusion planner on random maps (9 min), HMA* on the papers' maps (3 min), the any-angle bound over 1,080 maps and every planner, and the
      # 1-vs-2-thread sweep of the whole default planner set (killed at 464 s on 2 cores; that
      # determinism runs in the plain suite, and the sweep suite runs under TSan below); and,
      # measured at 100-250 s each under ASan on 2 cores (2026-12-02), the fusion planners' three
      # simulation suites and their 1-vs-2-thread sweep, and the CLI resume script's sweeps of
      # 1,200 maps (resume runs under ASan in cli_interrupt_isolated, cli_shard_merge and the
      # sweep suite). Of the planner contract of DWA and the three fusion planners, the two
      # tests that replan one long plan many times (DeadlineCutsEveryPhaseOfALongPlan,
      # WaypointCountIsThatOfThePathReturned: 37-70 s each under ASan, 2026-12-03): their other
      # contract tests run the same code here; and for fusion_alt_dwa and fusion_kin_dwa (12-16 s
      # each) the work-counter and same-seed contract tests, which run the one fusion loop of
      # fusion_astar_dwa's with other parameters (their global planners have contracts of their
      # own here). The same code runs under ASan in the smaller
      # tests of each suite (Fusion.SameSeedSameTrajectory, ...). Also left out: the Python
      # report scripts and the HTML report in Chromium (plot_scripts, html_report: no C++ of ours
      # runs there), and cli_plugin, which installs the package and builds the example plugin
      # against it (minutes of cmake and compiling): plugin loading (engine/plan/plugins.cpp) is then
      # tested in the plain suite only. And the planner contract of OMPL's four optimising
      # planners (10 s each in Release, mostly inside OMPL's own, uninstrumented library): the
      # adapter runs under ASan through the contract of ompl_rrt, ompl_rrtconnect, ompl_prm and
      # ompl_prmstar and test_ompl_sweep. The CLI scripts that run sweeps size them to the
      # sanitized build (AGV_SANITIZED, tests/CMakeLists.txt). Long tests first: ctest's cost
      # data seeded from tests/ctest_costs_asan.txt (measured under ASan on 2 cores).
      seed_costs build-asan tests/ctest_costs_asan.txt
      ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1:check_initialization_order=1:strict_init_order=1 \
      UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
        ctest --test-dir build-asan --output-on-failure -j "$jobs" -LE long \
        -E "${ASAN_CTEST_EXCLUDE-$asan_exclude}" ${CTEST_ARGS:-}
      ;;
    tsan)
      tsan_tbb
      configure build-tsan thread -DTBB_DIR="$root/build-tsan/tbb/install/lib/cmake/TBB"
      cmake --build build-tsan -j "$jobs" --target agvbench test_sweep
      for bin in build-tsan/agvbench build-tsan/tests/test_sweep; do
        # ldd's whole output is captured first: `ldd | grep -q` under pipefail fails when grep
        # exits at its first match and ldd then dies of SIGPIPE (issue 12).
        libs=$(ldd "$bin")
        [[ $libs == *"build-tsan/tbb/install/lib/libtbb"* ]] ||
          { echo "sanitize: $bin does not load the TSan-built libtbb" >&2; exit 1; }
      done
      echo "sanitize: tsan build took $(( $(date +%s) - start )) s"
      export TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1"
      tmp=$(mktemp -d)
      trap 'rm -rf "$tmp"' EXIT
      # Every planner of the default sweep on its 32 cells, 2 maps each (fusion and DWA 1, on
      # their scope's 16 cells), on 4 threads: races need threads working at once on every
      # planner's code, not many maps (the 100-map sweep would take hours under TSan).
      sed 's/"maps_per_cell": *100/"maps_per_cell": 2/; s/"maps_per_cell": *20}/"maps_per_cell": 1}/' \
        configs/default.json >"$tmp/default_tsan.json"
      [ "$(grep -c '"maps_per_cell": [12][,}]' "$tmp/default_tsan.json")" = 5 ] ||
        { echo "sanitize: configs/default.json's maps_per_cell values are not the ones shrunk here" >&2; exit 1; }
      build-tsan/agvbench run "$tmp/default_tsan.json" --threads 4 --quiet --out "$tmp/default.json" \
        --runs-out "$tmp/default.jsonl"
      # The sweep tests of the suite, the ones that run sweeps on threads (the Config.*,
      # OutputPaths.*, JournalWriter.*, ... tests there parse or write on one thread: the ASan
      # run covers them), but the 1-vs-2-thread determinism of the reduced default sweep: 200 s
      # under TSan on 2 cores (2026-12-04), for threads the sweep above already runs on every
      # planner; it runs in the plain suite.
      build-tsan/tests/test_sweep --gtest_brief=1 \
        --gtest_filter='Sweep.*:-Sweep.ReportIsIdenticalOnOneAndTwoThreads'
      ;;
    *) echo "sanitize: unknown part '$part' (asan or tsan)" >&2; exit 2 ;;
  esac
  echo "sanitize: $part took $(( $(date +%s) - start )) s"
done
