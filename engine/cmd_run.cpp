// `agvbench run`, `validate` and `list`.
#include <signal.h>
#include <tbb/info.h>

#include <atomic>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>
#include <tuple>

#include "algos/registry.h"
#include "engine/cli_numbers.h"
#include "engine/commands.h"
#include "engine/environment.h"
#include "engine/journal.h"
#include "engine/output_paths.h"
#include "engine/report.h"
#include "engine/results_db.h"
#include "engine/sweep_runner.h"

#ifndef AGV_SOURCE_DIR
#define AGV_SOURCE_DIR "."
#endif

namespace agv {

namespace {

std::atomic<bool> g_stop{false};
std::atomic<bool> g_cut{false};
static_assert(std::atomic<bool>::is_always_lock_free, "set from a signal handler");

// The interruption policy (README "Long sweeps", Interruption): a first SIGINT stops taking
// map tasks and lets the runs in flight finish and be recorded; SIGTERM, or a second signal,
// also cuts the runs in flight short (isolated workers are killed; those runs are not recorded
// and run again on resume). Either way the report is written, marked incomplete.
extern "C" void request_stop(int sig) {
  if (g_stop.exchange(true) || sig == SIGTERM) g_cut.store(true);
}

void install_stop_handlers() {
  struct sigaction sa {};
  sa.sa_handler = request_stop;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
}

std::pair<int, int> parse_shard(const std::string& text) {
  const auto slash = text.find('/');
  if (slash == std::string::npos)
    throw InputError("--shard: expected i/N with 0 <= i < N, got \"" + text + "\"");
  constexpr IntRange kShardRange{0, std::numeric_limits<int>::max()};
  const auto i = parse_cli_integer(text.substr(0, slash), "--shard (i of i/N)", kShardRange);
  const auto n =
      parse_cli_integer(text.substr(slash + 1), "--shard (N of i/N)", {1, kShardRange.hi});
  if (i >= n) throw InputError("--shard: expected i/N with 0 <= i < N, got \"" + text + "\"");
  return {static_cast<int>(i), static_cast<int>(n)};
}

// "16 cells x 100 maps x 13 planners = 20800 runs", or, with scoped planners, what they leave.
std::string run_count_text(const SweepConfig& config, const SweepPlan& plan) {
  const long long full = plan.map_tasks() * static_cast<long long>(config.planners.size());
  const long long runs = scheduled_runs(config, plan);
  bool uniform = true;  // map sources' cells hold as many maps as their files have queries
  for (const auto& cell : plan.cells) uniform = uniform && cell.maps == plan.cells.front().maps;
  std::string text =
      uniform ? std::to_string(plan.cells.size()) + " cells x " +
                    std::to_string(plan.cells.empty() ? 0 : plan.cells.front().maps) + " maps x "
              : std::to_string(plan.cells.size()) + " cells, " + std::to_string(plan.map_tasks()) +
                    " maps x ";
  text += std::to_string(config.planners.size()) + " planners = ";
  if (runs == full) return text + std::to_string(runs) + " runs";
  return text + std::to_string(full) + ", of which " + std::to_string(runs) +
         " runs are scheduled (planners with an \"only\" scope)";
}

// Every path `run` reads or writes, checked before anything is written (engine/output_paths.h).
void check_run_paths(const RunCommand& cmd, const std::string& config_path,
                     const SweepConfig& config, SweepOptions& options) {
  const bool resume = !options.resume_path.empty();
  if (resume && !options.runs_path.empty()) {
    if (!same_file(options.runs_path, options.resume_path))
      throw InputError(
          "--resume: the journal is appended to; --runs-out must be empty or the same file");
    options.runs_path = options.resume_path;  // the same journal, however spelled
  }
  const OutputPath journal = resume
                                 ? OutputPath{"--resume", options.resume_path, OutputKind::appended}
                                 : OutputPath{cmd.runs_out.empty() ? "runs" : "--runs-out",
                                              options.runs_path, OutputKind::new_journal};
  std::vector<InputPath> inputs = {{"config file", config_path}};
  for (const auto& g : config.generators)  // a map source's files are inputs too
    if (g.files)
      for (const auto& f : g.files->files) inputs.push_back({"map file", f.path});
  check_paths(inputs, {{cmd.out.empty() ? "report" : "--out", config.report_path},
                       journal,
                       {"--db", cmd.db, OutputKind::database}});
  if (!cmd.db.empty()) check_results_db(cmd.db, "--db");
  ignore_file_size_signal();
}

// The report, also when the journal failed (then a failure of both is named in one message).
void write_report(const SweepConfig& config, const SweepResults& results) {
  try {
    write_json_atomic(build_report(config, results), config.report_path);
  } catch (const std::runtime_error& e) {
    if (results.journal_error.empty()) throw;
    throw std::runtime_error(results.journal_error + "; and the report: " + e.what());
  }
}

// run --db: the sweep as one experiment of the database, with the failure messages of its
// journal when it wrote one (the slots keep no messages).
void write_database(const RunCommand& cmd, const SweepConfig& config, const SweepResults& results,
                    const std::string& journal) {
  RunMessages messages;
  if (!journal.empty()) read_run_messages(journal, results, messages);
  const nlohmann::json report = build_report(config, results);
  const std::int64_t id = append_experiment(cmd.db, {&config, &results, &report, &messages, "run",
                                                     environment_json(results.threads), "--db"});
  if (!cmd.quiet)
    std::fprintf(stderr, "agvbench: experiment %lld of %s\n", static_cast<long long>(id),
                 cmd.db.c_str());
}

}  // namespace

// The default config is found from any working directory: first as given, then in the checkout
// the binary was built from.
std::string locate_config(const std::string& path) {
  namespace fs = std::filesystem;
  if (fs::exists(path) || fs::path(path).is_absolute()) return path;
  const fs::path in_source = fs::path(AGV_SOURCE_DIR) / path;
  if (fs::exists(in_source)) return in_source.string();
  return path;
}

namespace {

// oneTBB runs a sweep on at most its default concurrency (the CPUs this process may use), however
// many threads are asked for; the report and summary give the number that ran.
int threads_that_run(int asked) {
  const int available = tbb::info::default_concurrency();
  if (asked <= available) return asked;
  std::fprintf(stderr, "agvbench: %d threads asked for; %d run (the CPUs this process may use)\n",
               asked, available);
  return available;
}

}  // namespace

int command_run(const RunCommand& cmd) {
  const std::string config_path = locate_config(cmd.config);
  SweepConfig config = load_config(config_path);
  if (cmd.threads >= 0) config.threads = cmd.threads;
  config.threads = threads_that_run(config.threads);
  if (!cmd.out.empty()) config.report_path = cmd.out;
  if (!cmd.runs_out.empty()) config.runs_path = cmd.runs_out;

  SweepOptions options;
  options.threads = config.threads;
  options.progress = !cmd.quiet;
  // A resumed sweep appends to the journal it restores: run_sweep refuses another --runs-out
  // (and the config's "runs" field does not apply).
  options.runs_path = !cmd.runs_out.empty() ? cmd.runs_out
                      : cmd.resume.empty()  ? config.runs_path
                                            : "";
  options.resume_path = cmd.resume;
  check_run_paths(cmd, config_path, config, options);
  if (!cmd.shard.empty())
    std::tie(options.shard_index, options.shard_count) = parse_shard(cmd.shard);
  options.isolation.enabled = cmd.isolate;
  options.isolation.hard_limit_s = cmd.isolate_timeout_s;
  options.isolation.memory_mb = cmd.isolate_memory_mb;
  options.stop = &g_stop;
  options.cut_short = &g_cut;
  install_stop_handlers();
  const SweepPlan plan = plan_sweep(config);
  if (!cmd.quiet) {
    std::fprintf(stderr, "agvbench: sweep \"%s\": %s\n", config.name.c_str(),
                 run_count_text(config, plan).c_str());
  }
  SweepResults results = run_sweep(config, options);
  write_report(config, results);
  // An interrupted sweep is not appended: its resume is (the same runs and more).
  if (!cmd.db.empty() && results.journal_error.empty() && !results.interrupted)
    write_database(cmd, config, results,
                   options.resume_path.empty() ? options.runs_path : options.resume_path);
  if (!results.journal_error.empty()) {
    // The runs the journal lost are not in the report either: a resume runs them again.
    const Coverage coverage = coverage_of(results);
    std::fprintf(stderr,
                 "agvbench: failed: %s; the sweep stopped with %lld of %lld runs recorded; "
                 "report (marked incomplete): %s; once the cause is fixed, continue with "
                 "--resume %s\n",
                 results.journal_error.c_str(), static_cast<long long>(coverage.runs_present),
                 static_cast<long long>(coverage.runs_expected), config.report_path.c_str(),
                 (options.resume_path.empty() ? options.runs_path : options.resume_path).c_str());
    return 1;
  }
  if (results.interrupted) {
    std::fprintf(stderr,
                 "agvbench: interrupted: %lld runs done this time, %lld restored; report (marked "
                 "incomplete): %s; resume with --resume %s\n",
                 static_cast<long long>(results.executed_runs),
                 static_cast<long long>(results.restored_runs), config.report_path.c_str(),
                 !options.resume_path.empty() ? options.resume_path.c_str()
                 : options.runs_path.empty()  ? "JOURNAL (none was written: use --runs-out)"
                                              : options.runs_path.c_str());
    if (!cmd.db.empty())
      std::fprintf(stderr,
                   "agvbench: nothing appended to %s (an interrupted sweep is appended when its "
                   "--resume completes it)\n",
                   cmd.db.c_str());
    return 130;
  }
  if (!cmd.quiet) {
    std::cout << summary_table(config, results);
    std::printf(
        "\n%lld runs in %.2f s on %d threads (%.0f runs/s)%s; report: %s\n",
        static_cast<long long>(results.executed_runs), results.wall_s, results.threads,
        results.wall_s > 0 ? static_cast<double>(results.executed_runs) / results.wall_s : 0.0,
        results.restored_runs > 0
            ? (", " + std::to_string(results.restored_runs) + " restored").c_str()
            : "",
        config.report_path.c_str());
  }
  return 0;
}

int command_merge(const std::string& config_path, const std::vector<std::string>& journals,
                  const std::string& out) {
  const std::string located = locate_config(config_path);
  const SweepConfig config = load_config(located);
  const std::string path = out.empty() ? config.report_path : out;
  std::vector<InputPath> inputs = {{"config file", located}};
  for (const auto& j : journals) inputs.push_back({"journal", j});
  check_paths(inputs, {{out.empty() ? "report" : "--out", path}});
  ignore_file_size_signal();
  SweepResults results = empty_results(config);
  const std::string hash = config_hash(config);
  for (const auto& j : journals) restore_journal(j, hash, results);
  update_completeness(results);
  write_json_atomic(build_report(config, results), path);
  const Coverage coverage = coverage_of(results);
  std::printf("merged %zu journals: %lld of %lld runs present%s; report: %s\n", journals.size(),
              static_cast<long long>(coverage.runs_present),
              static_cast<long long>(coverage.runs_expected),
              results.complete ? "" : " (INCOMPLETE coverage: the report says so)", path.c_str());
  return results.complete ? 0 : 1;
}

int command_validate(const std::string& config_path) {
  const SweepConfig config = load_config(config_path);
  // The paths a plain `run CONFIG` would write (--out, --runs-out and --resume are run's).
  check_paths(
      {{"config file", config_path}},
      {{"report", config.report_path}, {"runs", config.runs_path, OutputKind::new_journal}});
  const SweepPlan plan = plan_sweep(config);
  std::printf("%s: ok: %s, about %s held in memory\n", config_path.c_str(),
              run_count_text(config, plan).c_str(), bytes_text(sweep_size(config).bytes).c_str());
  return 0;
}

}  // namespace agv
