#!/usr/bin/env bash
# Issue 17 parts 1-2: agvbench installed into a fresh prefix, the example plugin
# (examples/plugin_planner) configured and built against that prefix ONLY (a copy of its sources,
# so nothing can reach into the source or build tree), listed, and swept next to astar: every
# path valid, gbfs never shorter than the optimal astar on the same map, its collision checks
# counted by the engine, 1 and 2 threads and --isolate identical in every non-timing field, the
# config's "plugins" and --plugin the same sweep, a resume refused once the plugin file changed
# (naming the plugin).
# Then the broken plugins, each built here: another agvbench version, another plugin ABI, no
# entry point, an unresolved symbol, a planner name of a built-in planner, a second plugin's
# planner or plugin name, and a file that is no library: each exit 2 with a message naming it.
# Usage: test_plugin.sh CMAKE BUILD_DIR SOURCE_DIR
set -u
cmake=$1
build=$2
src=$3
same=$src/slurm/same_report.py
source "$(dirname "$0")/lib.sh"
# The plugins are built with agvbench's own compiler (the loader insists on the same toolchain),
# through its compiler launcher (ccache) when it has one.
cache_value() { sed -n "s/^$1:[A-Z]*=//p" "$build/CMakeCache.txt"; }
tools=(-DCMAKE_CXX_COMPILER="$(cache_value CMAKE_CXX_COMPILER)")
launcher=$(cache_value CMAKE_CXX_COMPILER_LAUNCHER)
[ -n "$launcher" ] && tools+=(-DCMAKE_CXX_COMPILER_LAUNCHER="$launcher")
command -v ninja >/dev/null && tools+=(-G Ninja)

prefix=$work/prefix
"$cmake" --install "$build" --prefix "$prefix" >install.log 2>&1 || {
  cat install.log
  bad "cmake --install"
  finish test_plugin
  exit 1
}
bin=$prefix/bin/agvbench
[ -x "$bin" ] && [ -f "$prefix/include/agvbench/algos/plugin.h" ] &&
  [ -f "$prefix/include/agvbench/core/version.h" ] &&
  [ -f "$prefix/lib/cmake/agvbench/agvbenchConfig.cmake" ] && ok "installed: program, headers, package" ||
  bad "install layout"

# The example, copied out of the checkout, configured with the prefix alone.
cp -r "$src/examples/plugin_planner" example
if "$cmake" -S example -B example-build "${tools[@]}" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF >configure.log 2>&1 &&
  "$cmake" --build example-build >build.log 2>&1; then
  ok "example plugin configured and built against the install prefix"
else
  cat configure.log build.log | tail -30
  bad "example plugin build"
  finish test_plugin
  exit 1
fi
plugin=$(realpath example-build/libgbfs_plugin.so)
grep -q "agvbench_DIR:PATH=$prefix/lib/cmake/agvbench" example-build/CMakeCache.txt &&
  ok "find_package(agvbench) found the prefix" || bad "agvbench_DIR is not the prefix's"
# Neither the checkout nor its build tree, nor agvbench's own flags, reach the plugin's build.
flags=$(cat example-build/build.ninja example-build/CMakeFiles/*.dir/flags.make 2>/dev/null)
if grep -qF -- "$src/" <<<"$flags" || grep -qF -- "$build" <<<"$flags"; then
  bad "the example's build names the source or build tree"
else
  ok "the example's build names neither the source nor the build tree"
fi
grep -qE -- "-march=native|-Wconversion|-Wshadow" <<<"$flags" &&
  bad "agvbench's tuning or warnings leaked into the consumer" ||
  ok "no -march=native or agvbench warnings imposed on the consumer"

# list, text and JSON.
"$bin" list --plugin "$plugin" >list.txt 2>&1 && grep -q "^gbfs  -  greedy best-first" list.txt &&
  grep -q "plugin: gbfs_plugin 1.0.0" list.txt && ok "list --plugin shows gbfs and its plugin" ||
  bad "list --plugin: $(head -5 list.txt)"
"$bin" list --plugin "$plugin" --json >list.json 2>&1 && $py - list.json <<'EOF_PY' &&
import json, sys
doc = json.load(open(sys.argv[1]))
g = [p for p in doc["planners"] if p["name"] == "gbfs"]
assert len(g) == 1 and g[0]["plugin"] == "gbfs_plugin", g
names = {p["name"] for p in g[0]["params"]}
assert names == {"corner_rule", "heuristic", "check_every"}, names
(pl,) = doc["plugins"]
assert pl["name"] == "gbfs_plugin" and len(pl["sha256"]) == 64 and pl["planners"] == ["gbfs"], pl
assert any(p["name"] == "astar" and "plugin" not in p for p in doc["planners"])
EOF_PY
  ok "list --json: gbfs with its parameters and plugin record" || bad "list --json"
"$bin" list --json >plain.json && ! grep -q gbfs plain.json && ! grep -q '"plugins"' plain.json &&
  ok "list without --plugin: no plugin planner" || bad "list without --plugin shows plugins"

# plan and validate take --plugin.
"$bin" plan --plugin "$plugin" --planner gbfs --planner astar --size 24 --density 0.25 --seed 3 \
  --json --no-ascii >plan.json 2>plan.err && ok "plan --plugin --planner gbfs" ||
  bad "plan --plugin: $(cat plan.err)"

# The sweep: the config names the plugin by a path relative to its own folder.
mkdir -p sweep
cat >sweep/config.json <<'JSON'
{"name": "plugin-test", "seed": 17, "generators": ["uniform", "blocks"], "sizes": [40],
 "densities": [0.15, 0.3], "maps_per_cell": 12, "collision": {"corner_rule": "no_squeeze"},
 "plugins": ["../example-build/libgbfs_plugin.so"],
 "planners": ["astar", "gbfs",
              {"name": "gbfs", "label": "gbfs_manhattan", "params": {"heuristic": "manhattan"}}],
 "report": "unused.json"}
JSON
sed 's|"plugins": \[[^]]*\],||' sweep/config.json >sweep/no_plugins.json
runs=$((2 * 2 * 12 * 3))
"$bin" validate sweep/config.json >validate.txt 2>&1 && ok "validate with \"plugins\"" ||
  bad "validate: $(cat validate.txt)"
"$bin" validate sweep/no_plugins.json >/dev/null 2>validate2.txt
[ $? -eq 2 ] && grep -q 'unknown planner "gbfs"' validate2.txt &&
  ok "without the plugin, gbfs is an unknown planner (exit 2)" || bad "validate without plugin"
"$bin" validate sweep/no_plugins.json --plugin "$plugin" >/dev/null 2>&1 &&
  ok "validate --plugin" || bad "validate --plugin"

"$bin" run sweep/config.json --threads 1 --out t1.json --runs-out t1.jsonl --quiet &&
  "$bin" run sweep/config.json --threads 2 --out t2.json --quiet &&
  "$bin" run sweep/config.json --threads 2 "${isolate[@]}" --out iso.json --quiet &&
  "$bin" run sweep/no_plugins.json --plugin "$plugin" --threads 2 --out cli.json --quiet ||
  bad "a plugin sweep failed"
$py - t1.jsonl "$runs" "$plugin" t1.json <<'EOF_PY' && ok "every path valid; gbfs >= astar on every map; its checks counted; the report names the plugin" || bad "sweep records"
import collections, hashlib, json, sys
import os, subprocess
records = [json.loads(l) for l in subprocess.check_output([sys.executable, os.environ["AGV_JOURNAL_CHECK"], "--dump", sys.argv[1]], text=True).splitlines()]
assert len(records) == int(sys.argv[2]), len(records)
bad = [(r["planner"], r["outcome"]) for r in records if r["outcome"] != "success"]
assert not bad, bad[:5]
length = collections.defaultdict(dict)
for r in records:
    length[(r["cell"], r["map_index"])][r["planner"]] = r["metrics"]["path_length"]
    if r["planner_name"] == "gbfs":
        assert r["metrics"]["collision_checks"] > 0, r["metrics"]
        assert r["metrics"]["search_expansions"] > 0, r["metrics"]
longer = 0
for key, m in length.items():
    for label in ("gbfs", "gbfs_manhattan"):
        assert m[label] >= m["astar"] - 1e-9, (key, m)
        longer += m[label] > m["astar"] + 1e-9
assert longer > 0, "gbfs never longer than A*: not a greedy search?"
report = json.load(open(sys.argv[4]))
(pl,) = report["config"]["plugins"]
assert pl["path"] == sys.argv[3] and pl["name"] == "gbfs_plugin", pl
assert pl["sha256"] == hashlib.sha256(open(sys.argv[3], "rb").read()).hexdigest(), pl
print(f"{len(records)} runs, gbfs longer than A* on {longer} map-planner pairs")
EOF_PY
for r in t2 iso cli; do
  $py "$same" t1.json $r.json >/dev/null && ok "$r.json equals the 1-thread report (non-timing)" ||
    bad "$r.json differs: $($py "$same" t1.json $r.json)"
done

# A plugin library is a file the run reads (issue 28, class 1): no output replaces it, however
# spelled (a hard link), and validate says so too.
cp "$plugin" sweep/keep.so
ln sweep/keep.so sweep/hard.so
sed 's|"\.\./example-build/libgbfs_plugin.so"|"keep.so"|' sweep/config.json >sweep/keep.json
for args in "run sweep/keep.json --out sweep/hard.so --quiet" \
  "run sweep/keep.json --runs-out sweep/hard.so --quiet" \
  "run sweep/no_plugins.json --plugin sweep/keep.so --out sweep/hard.so --quiet" \
  "plan --plugin sweep/keep.so --planner gbfs --size 16 --json-out sweep/hard.so"; do
  # shellcheck disable=SC2086
  "$bin" $args >clash.txt 2>&1
  code=$?
  [ $code -eq 2 ] && grep -q 'sweep/hard.so": is the plugin library of gbfs_plugin' clash.txt &&
    cmp -s "$plugin" sweep/keep.so && ok "$args: refused, library intact" ||
    bad "$args: exit $code ($(head -c 200 clash.txt))"
done
sed 's|"report": *"[^"]*"|"report": "sweep/hard.so"|' sweep/keep.json >sweep/keep_report.json
"$bin" validate sweep/keep_report.json >clash.txt 2>&1
[ $? -eq 2 ] && grep -q 'report "sweep/hard.so": is the plugin library' clash.txt &&
  ok "validate names a report onto the plugin library" || bad "validate: $(head -c 200 clash.txt)"

# A plugin whose file name is not UTF-8 (issue 28, class 7) loads and its sweep's report is
# written, the name escaped.
odd_so="sweep/$(printf 'gbfs\xe9.so')"
cp "$plugin" "$odd_so"
"$bin" run sweep/no_plugins.json --plugin "$odd_so" --threads 2 --out odd.json --quiet 2>err.txt &&
  $py -c '
import json
r = json.load(open("odd.json", encoding="utf-8"))
(p,) = r["config"]["plugins"]
assert p["path"].endswith("/gbfs\ufffd.so") and r["complete"], p' &&
  ok "a plugin named in bytes that are not UTF-8 runs" || bad "odd plugin name: $(head -c 300 err.txt)"

# export takes --plugin as run does (issue 28, class 8): the journal of a sweep that loaded the
# plugin on the command line is exported with it; without it, the unknown planner says how.
"$bin" run sweep/no_plugins.json --plugin "$plugin" --threads 2 --out ex.json --runs-out ex.jsonl \
  --quiet && "$bin" export ex.jsonl --config sweep/no_plugins.json --plugin "$plugin" \
  --sqlite ex.db >ex.txt 2>&1 && ok "export --plugin: $(cat ex.txt)" || bad "export --plugin: $(cat ex.txt)"
"$bin" export ex.jsonl --config sweep/no_plugins.json --sqlite ex2.db >ex.txt 2>&1
[ $? -eq 2 ] && grep -q 'unknown planner "gbfs".*loaded, with --plugin' ex.txt && [ ! -e ex2.db ] &&
  ok "export without the plugin: exit 2, how to load it named" || bad "export without --plugin: $(cat ex.txt)"

# A resume knows the plugin's content: a changed file is refused.
cp "$plugin" sweep/copy.so
sed 's|"\.\./example-build/libgbfs_plugin.so"|"copy.so"|' sweep/config.json >sweep/copy.json
"$bin" run sweep/copy.json --threads 1 --out copy.json --runs-out copy.jsonl --quiet || bad "copy run"
printf 'x' >>sweep/copy.so
"$bin" run sweep/copy.json --threads 1 --out copy2.json --resume copy.jsonl --quiet >resume.txt 2>&1
rc=$?
[ $rc -eq 2 ] && grep -q 'plugin "gbfs_plugin" (.*copy.so) changed since the journal was written (sha256 [0-9a-f]\{64\} then, [0-9a-f]\{64\} now)' resume.txt &&
  ok "resume refused after the plugin file changed, naming it ($(head -c 150 resume.txt))" ||
  bad "resume after the plugin changed: exit $rc, $(head -c 300 resume.txt)"

# Broken plugins, built from one source: the ones that differ in a symbol (no entry point, an
# unresolved one) by a definition each, the ones that differ in what they declare (ABI, version,
# plugin and planner names) in one library reading them from the environment (AGV_BAD_*), so
# that each of those cases costs a process, not a compile.
mkdir -p bad
cat >bad/bad.cpp <<'EOF_CPP'
#include <cstdlib>
#include <memory>
#include <vector>
#include "agvbench/algos/plugin.h"
#include "agvbench/algos/search/astar.h"
const char* env_or(const char* key, const char* fallback) {
  const char* v = std::getenv(key);
  return v != nullptr && *v != '\0' ? v : fallback;
}
#ifdef UNRESOLVED
void agvbench_test_no_such_function();
#endif
namespace {
void add(void* out) {
#ifdef UNRESOLVED
  agvbench_test_no_such_function();
#endif
  agv::PlannerInfo info = agv::astar_planner();  // the built-in A*'s entry, renamed
  info.name = env_or("AGV_BAD_PLANNER", PLANNER_NAME);
  static_cast<std::vector<agv::PlannerInfo>*>(out)->push_back(std::move(info));
}
}  // namespace
#ifndef NO_ENTRY
extern "C" AGVBENCH_PLUGIN_EXPORT const AgvPlugin* agvbench_plugin_v1(void) {
  static const AgvPlugin plugin = {
      {std::atoi(env_or("AGV_BAD_ABI", AGVBENCH_PLUGIN_STR(AGVBENCH_PLUGIN_ABI))),
       env_or("AGV_BAD_VERSION", AGVBENCH_VERSION), AGVBENCH_PLUGIN_TOOLCHAIN, __VERSION__},
      env_or("AGV_BAD_PLUGIN", PLUGIN_NAME), "0.1", add};
  return &plugin;
}
#else
extern "C" AGVBENCH_PLUGIN_EXPORT int agvbench_plugin_v0(void) { return 0; }
#endif
EOF_CPP
# One more library whose misbehaviour the environment picks (AGV_MISBEHAVE), so that every
# case below costs one compile: a throw that is not a std::exception, a null factory, malformed
# parameter and counter declarations, exit() while loading or while planning.
cat >bad/misbehave.cpp <<'EOF_CPP'
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>
#include <fcntl.h>
#include <unistd.h>
#include "agvbench/algos/plugin.h"
#include "agvbench/algos/search/astar.h"
namespace {
class ExitPlanner : public agv::Planner {
 public:
  agv::PlanResult plan(const agv::PlanRequest&) const override { std::exit(0); }
};
std::unique_ptr<agv::Planner> make_exit(const agv::Params&) { return std::make_unique<ExitPlanner>(); }
std::unique_ptr<agv::Planner> make_throw(const agv::Params&) { throw 42; }
std::unique_ptr<agv::Planner> make_null(const agv::Params&) { return nullptr; }
// A* whose result is then spoilt as the mode says: a NaN point in its path, an extra metric
// named as one the engine measures, one given twice.
class SpoiltAStar : public agv::Planner {
 public:
  explicit SpoiltAStar(std::unique_ptr<agv::Planner> inner) : inner_(std::move(inner)) {}
  agv::PlanResult plan(const agv::PlanRequest& request) const override {
    const char* env = std::getenv("AGV_MISBEHAVE");
    const std::string mode = env ? env : "";
    // A child that leaves the worker's process group and hangs, its pid appended to a file.
    if (mode == "fork_setsid" && ::fork() == 0) {
      ::setsid();
      if (const char* file = std::getenv("AGV_STRAY_PIDS")) {
        char line[32];
        const int n = std::snprintf(line, sizeof line, "%d\n", static_cast<int>(::getpid()));
        const int fd = ::open(file, O_WRONLY | O_APPEND | O_CREAT, 0644);
        if (fd >= 0 && ::write(fd, line, static_cast<size_t>(n)) == n) ::close(fd);
      }
      for (;;) ::pause();
    }
    agv::PlanResult r = inner_->plan(request);
    if (mode == "nan_path" && r.path.size() >= 2) r.path[1] = {std::nan(""), std::nan("")};
    if (mode == "reserved_extra") r.extra.push_back({"path_length", 0.0});
    if (mode == "extra_twice") r.extra.insert(r.extra.end(), {{"mine", 1.0}, {"mine", 2.0}});
    if (mode == "rule_out_of_range") {  // a "no path" whose rule the engine would index by
      r = agv::PlanResult::failed(agv::Failure::no_path, "none");
      r.rule = static_cast<agv::CornerRule>(7);
    }
    if (mode == "failure_out_of_range") r.failure = static_cast<agv::Failure>(42);
    if (mode == "phase_negative") r.phases.push_back({"forged", -5});
    if (mode == "phase_too_long") r.phases.push_back({"forged", std::int64_t{1} << 50});
    return r;
  }
 private:
  std::unique_ptr<agv::Planner> inner_;
};
decltype(agv::PlannerInfo::make) g_astar_make = nullptr;
std::unique_ptr<agv::Planner> make_spoilt(const agv::Params& p) {
  return std::make_unique<SpoiltAStar>(g_astar_make(p));
}
void add(void* out) {
  const char* env = std::getenv("AGV_MISBEHAVE");
  const std::string mode = env ? env : "";
  agv::PlannerInfo info = agv::astar_planner();
  info.name = "misbehave_astar";
  using agv::ParamSpec;
  if (mode == "throw_int") throw 42;
  if (mode == "exit_in_load") std::exit(0);
  if (mode == "null_make") info.make = nullptr;
  if (mode == "param_empty_name") info.params.push_back(ParamSpec::number("", 1, 0, 2, "x"));
  if (mode == "param_twice") info.params.push_back(info.params.front());
  if (mode == "param_default_outside") info.params.push_back(ParamSpec::number("w", 5, 0, 1, ""));
  if (mode == "param_empty_range") info.params.push_back(ParamSpec::integer("n", 3, 5, 1, ""));
  if (mode == "param_no_choices") info.params.push_back(ParamSpec::choice("c", "a", {}, ""));
  if (mode == "param_default_not_a_choice")
    info.params.push_back(ParamSpec::choice("c", "z", {"a", "b"}, ""));
  if (mode == "counter_unknown") info.counters.push_back({"expansions", "nodes"});
  if (mode == "exit_in_plan") info.make = make_exit;
  if (mode == "make_throw_int") info.make = make_throw;
  if (mode == "make_null") info.make = make_null;
  if (mode == "planner_name_markup") info.name = "bad/<b>name</b> x";
  if (mode == "nan_path" || mode == "reserved_extra" || mode == "extra_twice" ||
      mode == "phase_negative" || mode == "phase_too_long" || mode == "fork_setsid" ||
      mode == "rule_out_of_range" || mode == "failure_out_of_range") {
    g_astar_make = info.make;
    info.make = make_spoilt;
  }
  static_cast<std::vector<agv::PlannerInfo>*>(out)->push_back(std::move(info));
}
}  // namespace
extern "C" AGVBENCH_PLUGIN_EXPORT const AgvPlugin* agvbench_plugin_v1(void) {
  const char* env = std::getenv("AGV_MISBEHAVE");
  if (env != nullptr && std::string(env) == "entry_throw_int") throw 42;
  static const AgvPlugin plugin = {
      {AGVBENCH_PLUGIN_ABI, AGVBENCH_VERSION, AGVBENCH_PLUGIN_TOOLCHAIN, __VERSION__}, "misbehave",
      "0.1", add};
  return &plugin;
}
EOF_CPP
cat >bad/CMakeLists.txt <<'EOF_CM'
cmake_minimum_required(VERSION 3.22)
project(bad_plugins LANGUAGES CXX)
find_package(agvbench CONFIG REQUIRED)
function(bad_plugin name)
  add_library(${name} MODULE bad.cpp)
  target_link_libraries(${name} PRIVATE agvbench::plugin)
  target_compile_definitions(${name} PRIVATE ${ARGN})
endfunction()
# identity: well-formed unless AGV_BAD_ABI, AGV_BAD_VERSION, AGV_BAD_PLUGIN or AGV_BAD_PLANNER
# say otherwise.
bad_plugin(identity PLUGIN_NAME="astar2_plugin" PLANNER_NAME="astar2")
bad_plugin(no_entry NO_ENTRY PLUGIN_NAME="no_entry" PLANNER_NAME="x")
bad_plugin(unresolved UNRESOLVED PLUGIN_NAME="unresolved" PLANNER_NAME="u_astar")
add_library(misbehave MODULE misbehave.cpp)
target_link_libraries(misbehave PRIVATE agvbench::plugin)
# A program of one's own on the installed static libraries (no plugin): the imported targets
# carry their dependencies.
add_executable(consumer consumer.cpp)
target_link_libraries(consumer PRIVATE agvbench::engine)
EOF_CM
cat >bad/consumer.cpp <<'EOF_CPP'
#include <cstdio>
#include "agvbench/algos/planner.h"
#include "agvbench/algos/registry.h"
#include "agvbench/engine/plan/config_loader.h"
int main() {
  agv::Grid grid(9, 9);
  for (int y = 0; y < 8; ++y) grid.set_blocked(4, y, true);
  agv::ConfiguredPlanner astar = agv::configure_planner("astar", nlohmann::json::object(), "astar");
  agv::Rng rng(1, 2);
  agv::Scratch scratch;
  const agv::PlanResult r = agv::plan_checked(*astar.planner, {grid, {0, 0}, {8, 0}, rng, scratch});
  const agv::SweepConfig config = agv::parse_config({{"planners", {"astar"}}, {"maps_per_cell", 2}});
  std::printf("%s %zu %lld %s\n", agv::to_string(r.failure), r.path.size(),
              static_cast<long long>(*r.work.collision_checks), agv::config_hash(config).c_str());
}
EOF_CPP
"$cmake" -S bad -B bad-build "${tools[@]}" -DCMAKE_PREFIX_PATH="$prefix" >bad.log 2>&1 &&
  "$cmake" --build bad-build >>bad.log 2>&1 && ok "broken test plugins built" ||
  { tail -30 bad.log; bad "broken test plugins build"; }
b=$work/bad-build
# The wall at x = 4 is open at y = 8 only: the path goes round it, more than the 9 cells of the
# straight line, and the engine's counter has its checks.
"$b/consumer" >consumer.txt 2>&1 && $py - consumer.txt <<'EOF_PY' && ok "a program linked against agvbench::engine plans ($(cat consumer.txt))" || bad "consumer: $(cat consumer.txt)"
import sys
outcome, cells, checks, config_hash = open(sys.argv[1]).read().split()
assert outcome == "none" and int(cells) > 9 and int(checks) > 0 and len(config_hash) == 16
EOF_PY
"$bin" list --plugin "$b/libidentity.so" --json | grep -q '"astar2"' &&
  ok "a second well-formed plugin (astar under another name) loads" || bad "good_astar2"
echo "not a library" >notlib.so
expect_refusal() {  # WHAT PATTERN ARGS...: exit 2 and stderr matching PATTERN (AGV_BAD_* as set)
  local what=$1 pattern=$2
  shift 2
  "$bin" list "$@" >out.txt 2>err.txt
  local rc=$?
  if [ $rc -eq 2 ] && grep -qE -- "$pattern" err.txt; then
    ok "$what: exit 2, $(head -c 170 err.txt)"
  else
    bad "$what: exit $rc, $(cat err.txt)"
  fi
}
AGV_BAD_VERSION=0.0.1-old expect_refusal "another agvbench version" \
  'libidentity\.so.*built against agvbench 0\.0\.1-old' --plugin "$b/libidentity.so"
AGV_BAD_ABI=99 expect_refusal "another plugin ABI" 'libidentity\.so.*plugin ABI 99' \
  --plugin "$b/libidentity.so"
expect_refusal "no entry point" 'libno_entry\.so.*no entry point agvbench_plugin_v1' \
  --plugin "$b/libno_entry.so"
expect_refusal "unresolved symbol" 'libunresolved\.so.*agvbench_test_no_such_function' \
  --plugin "$b/libunresolved.so"
AGV_BAD_PLANNER=astar expect_refusal "planner name of a built-in" \
  'libidentity\.so.*"astar" clashes with the built-in' --plugin "$b/libidentity.so"
AGV_BAD_PLANNER=gbfs expect_refusal "planner name of another plugin" \
  'libidentity\.so.*"gbfs" clashes with plugin "gbfs_plugin"' \
  --plugin "$plugin" --plugin "$b/libidentity.so"
AGV_BAD_PLUGIN=gbfs_plugin AGV_BAD_PLANNER=other_gbfs expect_refusal "plugin name of another plugin" \
  'libidentity\.so.*"gbfs_plugin" is taken' --plugin "$plugin" --plugin "$b/libidentity.so"
expect_refusal "not a library" 'notlib\.so.*not a shared library' --plugin notlib.so
expect_refusal "no such file" 'missing\.so' --plugin missing.so
# The same refusal from a config's "plugins", before anything is written.
sed 's|"\.\./example-build/libgbfs_plugin.so"|"../bad-build/libidentity.so"|' sweep/config.json \
  >sweep/bad.json
AGV_BAD_VERSION=0.0.1-old "$bin" run sweep/bad.json --out bad_report.json --quiet 2>err.txt
[ $? -eq 2 ] && grep -q 'plugins\[0\].*libidentity.*0\.0\.1-old' err.txt && [ ! -e bad_report.json ] &&
  ok "config \"plugins\" with a bad plugin: exit 2, nothing written" || bad "config bad plugin: $(cat err.txt)"
# Misbehaving plugins (issue 28, classes 5 and 6): each refused when it loads, exit 2 and one line
# naming the plugin and what is wrong, or, for a planner that calls exit() mid-run, exit 1 with a
# line saying so (never exit 0 without a report), and under --isolate a run recorded as a crash.
m=$b/libmisbehave.so
misbehaves() {  # MODE PATTERN
  AGV_MISBEHAVE=$1 expect_refusal "plugin: $1" "libmisbehave\.so.*$2" --plugin "$m"
}
misbehaves throw_int 'threw something that is not a std::exception'
misbehaves entry_throw_int 'agvbench_plugin_v1 threw something that is not a std::exception'
misbehaves planner_name_markup 'planner name "bad/<b>name</b> x" is not an identifier'
misbehaves null_make 'without a name or a make function'
misbehaves param_empty_name 'parameter "".*a name must be a word'
misbehaves param_twice 'parameter "[a-z_]+": declared twice'
misbehaves param_default_outside 'parameter "w" default: 5.* is outside \[0, 1\]'
misbehaves param_empty_range 'parameter "n": its range \[5, 1\] is empty'
misbehaves param_no_choices 'parameter "c": a choice without choices'
misbehaves param_default_not_a_choice 'parameter "c" default: "z" is not one of: a, b'
misbehaves counter_unknown 'work counter "expansions" is not one the engine knows'
AGV_MISBEHAVE=exit_in_load "$bin" list --plugin "$m" >out.txt 2>err.txt
rc=$?
[ $rc -eq 1 ] && grep -q 'libmisbehave\.so.*add_planners called exit()' err.txt &&
  ok "plugin: exit() in add_planners: exit 1, $(head -c 150 err.txt)" ||
  bad "plugin: exit() in add_planners: exit $rc, $(cat err.txt)"
sed 's|"\.\./example-build/libgbfs_plugin.so"|"../bad-build/libmisbehave.so"|; s|"gbfs",|"misbehave_astar",|; s|{"name": "gbfs", "label": "gbfs_manhattan", "params": {"heuristic": "manhattan"}}|"dijkstra"|' \
  sweep/config.json >sweep/exit.json
# Issue 49 class 2: a planner factory that throws something that is not a std::exception, or
# returns no planner, is bad input naming the plugin and the planner (validate, run and plan:
# exit 2, nothing written), never SIGABRT or SIGSEGV.
for mode in make_throw_int make_null; do
  pattern='plugin "misbehave".s planner "misbehave_astar": its make function (threw something that is not a std::exception|returned no planner)'
  AGV_MISBEHAVE=$mode "$bin" validate sweep/exit.json >out.txt 2>err.txt
  rc_validate=$?
  grep -qE "$pattern" err.txt || rc_validate=99
  AGV_MISBEHAVE=$mode "$bin" run sweep/exit.json --out make.json --quiet >out.txt 2>err.txt
  rc_run=$?
  grep -qE "$pattern" err.txt || rc_run=99
  AGV_MISBEHAVE=$mode "$bin" plan --plugin "$m" --planner misbehave_astar --no-ascii >out.txt 2>err.txt
  rc_plan=$?
  grep -qE "$pattern" err.txt || rc_plan=99
  [ "$rc_validate $rc_run $rc_plan" = "2 2 2" ] && [ ! -e make.json ] &&
    ok "plugin: $mode: validate, run and plan exit 2, $(head -c 150 err.txt)" ||
    bad "plugin: $mode: exits $rc_validate $rc_run $rc_plan, $(cat err.txt)"
done
AGV_MISBEHAVE=exit_in_plan "$bin" run sweep/exit.json --threads 2 --out exit.json --quiet >out.txt 2>err.txt
rc=$?
[ $rc -eq 1 ] && grep -q 'planner "misbehave_astar", in the middle of its run on map [0-9]* of cell .*, called exit()' err.txt &&
  ok "plugin: exit() in plan: exit 1, $(head -c 150 err.txt)" ||
  bad "plugin: exit() in plan: exit $rc, $(cat err.txt)"
AGV_MISBEHAVE=exit_in_plan "$bin" run sweep/exit.json --threads 2 "${isolate[@]}" --out exit_iso.json \
  --runs-out exit_iso.jsonl --quiet >out.txt 2>err.txt
rc=$?
$py - exit_iso.jsonl $((runs / 3)) <<'EOF_PY' && [ $rc -eq 0 ] && ok "plugin: exit() in plan under --isolate: every such run a crash, the sweep complete" || bad "plugin: exit() in plan under --isolate: exit $rc, $(tail -3 err.txt)"
import collections, json, sys
import os, subprocess
records = [json.loads(l) for l in subprocess.check_output([sys.executable, os.environ["AGV_JOURNAL_CHECK"], "--dump", sys.argv[1]], text=True).splitlines()]
by = collections.Counter((r["planner"], r["outcome"]) for r in records)
n = int(sys.argv[2])
assert by[("misbehave_astar", "crash")] == n and by[("astar", "success")] == n, by
EOF_PY
# Issue 49 class 1: a planner's child that leaves the worker's process group (setsid) and hangs
# does not outlive the sweep: agvbench, a child subreaper, adopts and kills it.
: >strays.txt
AGV_MISBEHAVE=fork_setsid AGV_STRAY_PIDS=$PWD/strays.txt "$bin" run sweep/exit.json --threads 2 \
  "${isolate[@]}" --out strays.json --quiet >out.txt 2>err.txt
rc=$?
sleep 0.2
forked=0 alive=0
while read -r pid; do
  forked=$((forked + 1))
  if [ -e "/proc/$pid" ] && ! grep -q '^State:[[:space:]]*Z' "/proc/$pid/status" 2>/dev/null; then
    alive=$((alive + 1))
    kill -9 "$pid" 2>/dev/null
  fi
done <strays.txt
[ $rc -eq 0 ] && [ "$forked" -gt 0 ] && [ "$alive" -eq 0 ] &&
  ok "plugin: setsid children of isolated runs: $forked started, none left after the sweep" ||
  bad "plugin: setsid children: exit $rc, $alive of $forked still running, $(tail -2 err.txt)"
# What a planner returns is judged, whoever wrote it: a path with a NaN point is invalid, in a
# sweep and in `scen`; an extra metric named as one the engine measures, or given twice, makes
# the run a crash (nothing of it recorded), and the measured value stands; so does an outcome or
# corner rule outside its enum.
spoilt() {  # MODE: the exit.json sweep with misbehave_astar spoilt so
  AGV_MISBEHAVE=$1 "$bin" run sweep/exit.json --threads 2 --out "$1.json" --runs-out "$1.jsonl" \
    --quiet >out.txt 2>err.txt || echo "run exit $?" >>err.txt
}
judged() {  # MODE OUTCOME MESSAGE_PATTERN
  spoilt "$1"
  $py - "$1.jsonl" $((runs / 3)) "$2" "$3" <<'EOF_PY' && ok "plugin: $1: every run $2, the measured metrics untouched" || bad "plugin: $1: $(tail -3 err.txt)"
import json, re, sys
import os, subprocess
records = [json.loads(l) for l in subprocess.check_output([sys.executable, os.environ["AGV_JOURNAL_CHECK"], "--dump", sys.argv[1]], text=True).splitlines()]
mine = [r for r in records if r["planner"] == "misbehave_astar"]
assert len(mine) == int(sys.argv[2]), len(mine)
assert all(r["outcome"] == sys.argv[3] for r in mine), {r["outcome"] for r in mine}
assert all(re.search(sys.argv[4], r.get("message", "")) for r in mine), mine[0].get("message")
assert all(r["metrics"].get("path_length") != 0.0 for r in mine), "a planner's extra replaced path_length"
EOF_PY
}
judged nan_path invalid_path 'not finite|NaN|nan'
judged reserved_extra crash 'extra metric "path_length" is a name the engine measures'
judged extra_twice crash 'extra metric "mine" given twice'
judged rule_out_of_range crash 'corner rule 7 is not one of'
judged failure_out_of_range crash 'outcome \(failure\) 42 is not one of'
judged phase_negative crash 'phase "forged" time -5 ns is negative'
judged phase_too_long crash 'phase "forged" time [0-9]+ ns is longer than the whole call'
# A small map with straight queries whose optima are plain: 5, 7 and 5 cells.
printf 'type octile\nheight 6\nwidth 8\nmap\n........\n........\n........\n........\n........\n........\n' >open.map
printf 'version 1\n0\topen.map\t8\t6\t0\t0\t5\t0\t5\n0\topen.map\t8\t6\t0\t2\t7\t2\t7\n0\topen.map\t8\t6\t3\t0\t3\t5\t5\n' >open.map.scen
AGV_MISBEHAVE=nan_path "$bin" scen --plugin "$m" --planner misbehave_astar open.map open.map.scen \
  --json >scen.json 2>err.txt
$py - scen.json <<'EOF_PY' && ok "plugin: scen counts a path with a NaN point as a failure, never a match" || bad "plugin: scen nan_path: $(head -c 300 scen.json) $(cat err.txt)"
import json, sys
doc = json.load(open(sys.argv[1]))
assert doc["failures"] > 0 and doc["mismatches"] >= doc["failures"], doc
EOF_PY
# A truncated copy of a good library: refused before the loader maps it (it would die of SIGBUS).
size=$(stat -c %s "$b/libidentity.so")
head -c $((size * 2 / 3)) "$b/libidentity.so" >trunc.so
expect_refusal "truncated library" 'trunc\.so.*truncated or damaged shared library' --plugin trunc.so
head -c 40 "$b/libidentity.so" >short.so
expect_refusal "library shorter than its ELF header" 'short\.so.*shorter than an ELF header' --plugin short.so
finish test_plugin
