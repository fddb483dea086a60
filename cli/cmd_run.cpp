// `agvbench run`: a sweep, its report, journal and database.
#include <signal.h>
#include <tbb/info.h>

#include <atomic>
#include <cstdio>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <tuple>

#include "cli/cli_numbers.h"
#include "cli/command.h"
#include "cli/locate_config.h"
#include "cli/option_checks.h"
#include "cli/progress_sink.h"
#include "cli/run_count.h"
#include "engine/outputs/database_sink.h"
#include "engine/outputs/journal.h"
#include "engine/outputs/report.h"
#include "engine/outputs/report_sink.h"
#include "engine/outputs/results_db.h"
#include "engine/plan/config_loader.h"
#include "engine/plan/files_read.h"
#include "engine/plan/output_paths.h"
#include "engine/plan/sweep_size.h"
#include "engine/sweep/sweep_runner.h"
#include "engine/system/environment.h"

namespace agv {

namespace {

struct RunCommand {
  std::string config = "configs/default.json";
  int threads = -1;  // -1: the config's value
  std::string out;   // overrides the config's report path
  std::string runs_out;
  std::string resume;  // journal to resume from (appended to)
  std::string shard;   // "i/N"
  bool isolate = false;
  double isolate_timeout_s = 0.0;  // 0: twice the config's time limit + 1 s
  long long isolate_memory_mb = 4096;
  bool quiet = false;
  std::string db;  // SQLite database the sweep is appended to as one experiment (results_db.h)
};

// --isolate-timeout: above the longest per-run limit a config can set, twice over (the default
// is 2 x time_limit_s + 1 s).
constexpr NumberRange kIsolateTimeoutRange{kTimeLimitRange.lo, 2 * kTimeLimitRange.hi + 1};

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

// Every path `run` reads or writes, checked before anything is written
// (engine/plan/output_paths.h).
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
  check_paths(files_read(config, config_path),
              {{cmd.out.empty() ? "report" : "--out", config.report_path},
               journal,
               {"--db", cmd.db, OutputKind::database}});
  if (!cmd.db.empty()) {
    check_results_db(cmd.db, "--db");
    check_sweep_size(config, true);  // --db keeps every run's slot to the end
  }
  ignore_file_size_signal();
}

// oneTBB runs a sweep on at most its default concurrency (the CPUs this process may use), however
// many threads are asked for; the report and summary give the number that ran.
int threads_that_run(int asked) {
  const int available = tbb::info::default_concurrency();
  if (asked <= available) return asked;
  std::fprintf(stderr, "agvbench: %d threads asked for; %d run (the CPUs this process may use)\n",
               asked, available);
  return available;
}

// The config as this run uses it: the command line's threads and paths over the config's.
SweepConfig run_config(const RunCommand& cmd, const std::string& config_path) {
  SweepConfig config = load_config(config_path);
  if (cmd.threads >= 0) config.threads = cmd.threads;
  config.threads = threads_that_run(config.threads);
  if (!cmd.out.empty()) config.report_path = cmd.out;
  if (!cmd.runs_out.empty()) config.runs_path = cmd.runs_out;
  return config;
}

// How the sweep runs, every path checked (check_run_paths) before anything is written.
SweepOptions run_options(const RunCommand& cmd, const std::string& config_path,
                         const SweepConfig& config) {
  SweepOptions options;
  options.threads = config.threads;
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
  return options;
}

int sink_failed(const SweepConfig& config, const SweepResults& results,
                const SweepOptions& options) {
  // The runs the journal lost are not in the report either: a resume runs them again.
  const Coverage coverage = coverage_of(results);
  std::fprintf(stderr,
               "agvbench: failed: %s; the sweep stopped with %lld of %lld runs recorded; "
               "report (marked incomplete): %s; once the cause is fixed, continue with "
               "--resume %s\n",
               results.sink_error.c_str(), static_cast<long long>(coverage.runs_present),
               static_cast<long long>(coverage.runs_expected), config.report_path.c_str(),
               journal_path_of(options).c_str());
  return 1;
}

int interrupted(const RunCommand& cmd, const SweepConfig& config, const SweepResults& results,
                const SweepOptions& options) {
  const std::string journal = journal_path_of(options);
  std::fprintf(stderr,
               "agvbench: interrupted: %lld runs done this time, %lld restored; report (marked "
               "incomplete): %s; resume with --resume %s\n",
               static_cast<long long>(results.executed_runs),
               static_cast<long long>(results.restored_runs), config.report_path.c_str(),
               journal.empty() ? "JOURNAL (none was written: use --runs-out)" : journal.c_str());
  if (!cmd.db.empty())
    std::fprintf(stderr,
                 "agvbench: nothing appended to %s (an interrupted sweep is appended when its "
                 "--resume completes it)\n",
                 cmd.db.c_str());
  return 130;
}

void print_summary(const SweepConfig& config, const SweepResults& results) {
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

// Exit code 130 when interrupted by SIGINT/SIGTERM (the report is written, marked incomplete).
int command_run(const RunCommand& cmd) {
  const std::string config_path = locate_config(cmd.config);
  const SweepConfig config = run_config(cmd, config_path);
  SweepOptions options = run_options(cmd, config_path, config);
  install_stop_handlers();
  SweepResults results = empty_results(config);
  // The sinks (engine/outputs/sweep_sink.h) after the journal: the report, then the database that
  // reads it, then the progress display.
  ReportSink report(config, config.report_path, !cmd.db.empty());
  std::optional<DatabaseSink> database;
  ProgressSink progress;
  options.sinks.push_back(&report);
  // The database reads every run's slot at the end (issue 46 stage 3b streams it instead).
  options.release_cells = cmd.db.empty();
  if (!cmd.db.empty()) options.sinks.push_back(&database.emplace(config, cmd.db, "--db", report));
  if (!cmd.quiet) {
    std::fprintf(stderr, "agvbench: sweep \"%s\": %s\n", config.name.c_str(),
                 run_count_text(config, results.plan).c_str());
    options.sinks.push_back(&progress);
  }
  run_sweep(config, results, options);
  if (database && database->experiment_id() && !cmd.quiet)
    std::fprintf(stderr, "agvbench: experiment %lld of %s\n",
                 static_cast<long long>(*database->experiment_id()), cmd.db.c_str());
  if (!results.sink_error.empty()) return sink_failed(config, results, options);
  if (results.interrupted) return interrupted(cmd, config, results, options);
  if (!cmd.quiet) print_summary(config, results);
  return 0;
}

}  // namespace

Command add_run_command(CLI::App& app) {
  auto cmd = std::make_shared<RunCommand>();
  auto* sub = app.add_subcommand("run", "run a sweep and write its JSON report");
  sub->add_option("config", cmd->config, "sweep config (default: configs/default.json)");
  sub->add_option("--threads", cmd->threads, "worker threads (0 = all)")
      ->transform(integer_in(kThreadsRange));
  sub->add_option("--out", cmd->out, "report path (overrides the config)");
  sub->add_option("--runs-out", cmd->runs_out, "JSON Lines file of per-run records");
  sub->add_option("--resume", cmd->resume,
                  "journal of an interrupted run: skip its runs, append to it");
  sub->add_option("--shard", cmd->shard, "i/N: run only the i-th of N slices (split by map)");
  sub->add_flag("--isolate", cmd->isolate, "run planners in worker processes (fault isolation)");
  sub->add_option("--isolate-timeout", cmd->isolate_timeout_s,
                  "hard wall-clock limit per run in seconds (default 2x time_limit_s + 1)")
      ->transform(number_in(kIsolateTimeoutRange));
  sub->add_option("--isolate-memory", cmd->isolate_memory_mb, "address-space cap per worker, MiB")
      ->transform(integer_in(kIsolateMemoryRange));
  sub->add_flag("--quiet", cmd->quiet, "no progress meter and no summary table");
  sub->add_option("--db", cmd->db, "SQLite database: append the sweep as one experiment");
  return {sub, [cmd] { return command_run(*cmd); }};
}

}  // namespace agv
