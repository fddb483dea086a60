#include "engine/sweep/isolated_worker.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <iostream>
#include <stdexcept>

#include "core/json_text.h"
#include "core/printable.h"
#include "engine/plan/config_loader.h"
#include "engine/sweep/map_task.h"
#include "engine/system/file_writes.h"
#include "engine/system/stray_children.h"

extern char** environ;

namespace agv {

namespace {

void write_all(int fd, const std::string& text) {
  std::size_t done = 0;
  if (write_whole(fd, text, done) != 0) throw std::runtime_error("worker pipe closed");
}

struct TaskRequest {
  std::int64_t task = 0;
  std::vector<std::size_t> planners;
};

// Reads {"task": t, "planners": [p, ...]} with t a map task of the sweep and each p a planner
// scheduled on it; returns why not, or "" when `out` holds the request.
std::string read_task_request(const std::string& line, const MapTaskContext& context,
                              TaskRequest& out) {
  const auto request = nlohmann::json::parse(line, nullptr, false);
  if (!request.is_object()) return "not a JSON object";
  for (const auto& [key, value] : request.items())
    if (key != "task" && key != "planners") return "unknown key \"" + key + "\"";
  const auto task = request.find("task");
  const std::int64_t tasks = context.plan.map_tasks();
  // The parser reads a non-negative integer as unsigned: a negative or fractional one is not.
  if (task == request.end() || !task->is_number_unsigned() ||
      task->get<std::uint64_t>() >= static_cast<std::uint64_t>(tasks))
    return "\"task\" must be a map task index in [0, " + std::to_string(tasks) + "), got " +
           (task == request.end() ? std::string("none") : json_text(*task));
  out.task = static_cast<std::int64_t>(task->get<std::uint64_t>());
  const auto planners = request.find("planners");
  if (planners == request.end() || !planners->is_array())
    return "\"planners\" must be an array of planner indices";
  const std::size_t count = context.config.planners.size();
  const SweepCell& cell = context.plan.cell_of(out.task);
  const int map_index = context.plan.map_index_of(out.task);
  out.planners.clear();
  for (const auto& p : *planners) {
    if (!p.is_number_unsigned() || p.get<std::uint64_t>() >= count)
      return "planner index " + json_text(p) + " is not in [0, " + std::to_string(count) + ")";
    const auto index = static_cast<std::size_t>(p.get<std::uint64_t>());
    if (map_index >= scoped_maps(context.config.planners[index], cell))
      return "planner " + std::to_string(index) + " is not scheduled on task " +
             std::to_string(out.task);
    out.planners.push_back(index);
  }
  return "";
}

// A worker is over: what its planners started and left behind (in the worker's group or, having
// left it, handed to us as orphans) is killed.
void forget_worker(pid_t pid) {
  LiveWorkers::remove(pid);
  LiveWorkers::kill_strays();
}

}  // namespace

WorkerProcess::WorkerProcess(std::vector<std::string> command, std::int64_t memory_mb,
                             std::string config_line, const std::atomic<bool>* cut_short)
    : command_(std::move(command)),
      memory_mb_(memory_mb),
      config_line_(std::move(config_line)),
      cut_short_(cut_short) {
  // A write to a worker that just died must be an error to handle, not a fatal SIGPIPE.
  ::signal(SIGPIPE, SIG_IGN);
  spawn();
}

WorkerProcess::~WorkerProcess() { stop(); }

void WorkerProcess::spawn() {
  int in_pipe[2], out_pipe[2];
  if (::pipe2(in_pipe, O_CLOEXEC) != 0 || ::pipe2(out_pipe, O_CLOEXEC) != 0)
    throw std::runtime_error("cannot create worker pipes");
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, in_pipe[0], STDIN_FILENO);
  posix_spawn_file_actions_adddup2(&actions, out_pipe[1], STDOUT_FILENO);
  // A process group of its own (pgid = its pid), set in the child before exec: a terminal's
  // SIGINT goes to the parent's group only, and the parent decides what happens to the runs.
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);
  posix_spawnattr_setpgroup(&attributes, 0);
  std::vector<std::string> args = command_;
  args.push_back("--memory-mb");
  args.push_back(std::to_string(memory_mb_));
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  // Orphans below the worker come to us (engine/system/stray_children.h); the worker is
  // registered before any other thread can sweep for strays.
  adopt_orphans();
  int rc = 0;
  {
    const LiveWorkers::SpawnLock registering;
    rc = posix_spawn(&pid_, argv[0], &actions, &attributes, argv.data(), environ);
    if (rc == 0) LiveWorkers::add(pid_);
  }
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  // And in the parent, as a shell does, so no window exists in which the child is still in our
  // group whatever the spawn implementation; EACCES (the child already ran exec, having set its
  // group itself) is the expected answer with glibc's vfork-style posix_spawn.
  if (rc == 0) ::setpgid(pid_, pid_);
  ::close(in_pipe[0]);
  ::close(out_pipe[1]);
  if (rc != 0) {
    ::close(in_pipe[1]);
    ::close(out_pipe[0]);
    pid_ = -1;
    throw std::runtime_error("cannot start worker " + command_.front() + ": " + std::strerror(rc));
  }
  to_child_ = in_pipe[1];
  from_child_ = out_pipe[0];
  buffer_.clear();
  std::string why;
  try {
    write_all(to_child_, config_line_ + "\n");
  } catch (const std::runtime_error&) {
    // Died before reading its config; the read below says how.
  }
  // Generous: the worker only parses the config and configures its planners.
  std::string line;
  const ReadStatus status = read_line(Clock::now() + std::chrono::seconds(60), line);
  if (status == ReadStatus::line) {
    const auto hello = nlohmann::json::parse(line, nullptr, false);
    if (hello.is_object() && hello.value("ready", false)) return;
    why = hello.is_object() && hello.contains("fatal") && hello["fatal"].is_string()
              ? hello["fatal"].get<std::string>()
              : "unexpected first line \"" + line.substr(0, 200) + "\"";
    stop();
  } else if (status == ReadStatus::timeout) {
    stop();
    why = "no answer within 60 s";
  } else if (status == ReadStatus::cut) {
    stop();
    throw RunsCut();
  } else {
    bool interrupted = false;
    std::int64_t cpu_ns = 0;
    why = describe_exit(interrupted, cpu_ns);
    stop();
    if (interrupted) throw RunsCut();
  }
  throw std::runtime_error("isolation worker failed to start: " + why);
}

WorkerProcess::ReadStatus WorkerProcess::read_line(Clock::time_point deadline, std::string& line) {
  for (;;) {
    const auto nl = buffer_.find('\n');
    if (nl != std::string::npos) {
      line = buffer_.substr(0, nl);
      buffer_.erase(0, nl + 1);
      return ReadStatus::line;
    }
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    if (left <= 0) return ReadStatus::timeout;
    if (cut_requested()) return ReadStatus::cut;
    // Short slices when a cut may be requested: a signal interrupts the poll of one thread only.
    const decltype(left) slice = cut_short_ != nullptr ? 100 : 1000;
    pollfd pfd{from_child_, POLLIN, 0};
    const int pr = ::poll(&pfd, 1, static_cast<int>(std::min(left, slice)));
    if (pr <= 0) continue;  // EINTR or a poll slice without data: check again
    char buf[65536];
    const ssize_t n = ::read(from_child_, buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return ReadStatus::closed;
    buffer_.append(buf, static_cast<std::size_t>(n));
  }
}

void WorkerProcess::stop() {
  if (pid_ > 0) {
    // The worker's whole process group (it leads one: spawn()), so that a process a planner
    // started dies with it.
    ::kill(-pid_, SIGKILL);
    int status = 0;
    while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
    forget_worker(pid_);
  }
  if (to_child_ >= 0) ::close(to_child_);
  if (from_child_ >= 0) ::close(from_child_);
  pid_ = -1;
  to_child_ = from_child_ = -1;
}

std::int64_t WorkerProcess::cpu_time_ns() const {
  clockid_t clock;
  timespec t{};
  if (pid_ <= 0 || ::clock_getcpuclockid(pid_, &clock) != 0 || ::clock_gettime(clock, &t) != 0)
    return -1;
  return static_cast<std::int64_t>(t.tv_sec) * 1'000'000'000 + t.tv_nsec;
}

std::string WorkerProcess::describe_exit(bool& interrupted, std::int64_t& cpu_ns) {
  int status = 0;
  pid_t r;
  rusage usage{};
  while ((r = ::wait4(pid_, &status, 0, &usage)) < 0 && errno == EINTR) {
  }
  cpu_ns =
      r > 0
          ? (static_cast<std::int64_t>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) * 1'000'000 +
             usage.ru_utime.tv_usec + usage.ru_stime.tv_usec) *
                1000
          : -1;
  ::kill(-pid_, SIGKILL);  // what its planner started, if anything is left of its group
  forget_worker(pid_);
  pid_ = -1;
  interrupted = false;
  if (r > 0 && WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    // Signals that ask a process to stop: someone interrupted the worker, its run did not fail.
    // (A fault is SIGSEGV, SIGABRT, SIGBUS, SIGFPE; the parent's own kills are SIGKILL.)
    interrupted = sig == SIGINT || sig == SIGTERM || sig == SIGHUP || sig == SIGQUIT;
    return std::string("worker killed by signal ") + std::to_string(sig) + " (" +
           (sigdescr_np(sig) ? sigdescr_np(sig) : "?") + ")";
  }
  if (r > 0 && WIFEXITED(status))
    return "worker exited with code " + std::to_string(WEXITSTATUS(status));
  return "worker vanished";
}

void WorkerProcess::start_task(std::int64_t task, std::span<const std::size_t> planners) {
  if (pid_ < 0) spawn();
  const nlohmann::json request = {
      {"task", task}, {"planners", std::vector<std::size_t>(planners.begin(), planners.end())}};
  try {
    write_all(to_child_, json_text(request) + "\n");
  } catch (const std::runtime_error&) {
    // Died between tasks; next_run's read reports the death.
  }
}

WorkerProcess::Reply WorkerProcess::next_run(double hard_limit_s) {
  Reply reply;
  const auto start = Clock::now();
  const auto deadline = start + std::chrono::duration_cast<Clock::duration>(
                                    std::chrono::duration<double>(hard_limit_s));
  const std::int64_t cpu_start = cpu_time_ns();
  const auto cpu_since_start = [cpu_start](std::int64_t now) {
    return cpu_start >= 0 && now >= cpu_start ? now - cpu_start : std::int64_t{-1};
  };
  // The reply's two lines, under one deadline.
  ReadStatus status = read_line(deadline, reply.map_line);
  if (status == ReadStatus::line) status = read_line(deadline, reply.run_line);
  reply.wall_ns =
      std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now() - start).count();
  switch (status) {
    case ReadStatus::line:
      reply.ok = true;
      return reply;
    case ReadStatus::timeout:
      reply.cpu_ns = cpu_since_start(cpu_time_ns());
      stop();
      reply.outcome = Outcome::timeout;
      reply.message = "killed at the hard limit of " + std::to_string(hard_limit_s) + " s";
      return reply;
    case ReadStatus::cut:
      stop();
      reply.cut = true;
      reply.message = "cut short by a stop request";
      return reply;
    case ReadStatus::closed: {
      reply.outcome = Outcome::crash;
      std::int64_t cpu_total = -1;
      reply.message = describe_exit(reply.cut, cpu_total);
      reply.cpu_ns = cpu_since_start(cpu_total);
      ::close(to_child_);
      ::close(from_child_);
      to_child_ = from_child_ = -1;
      return reply;
    }
  }
  return reply;
}

namespace {

// The worker's end of the protocol, on descriptors of its own: fd 0 and 1 are given to the
// planners as /dev/null and the worker's stderr, so that whatever a planner reads or prints
// (a debug line on stdout, bytes that are not text) never reaches the channel.
class Channel {
 public:
  Channel() {
    in_ = ::fcntl(STDIN_FILENO, F_DUPFD_CLOEXEC, 3);
    out_ = ::fcntl(STDOUT_FILENO, F_DUPFD_CLOEXEC, 3);
    if (in_ < 0 || out_ < 0) throw std::runtime_error("worker: cannot set up its channel");
    std::cout.flush();
    const int null = ::open("/dev/null", O_RDONLY | O_CLOEXEC);
    if (null < 0 || ::dup2(null, STDIN_FILENO) < 0 || ::dup2(STDERR_FILENO, STDOUT_FILENO) < 0)
      throw std::runtime_error("worker: cannot redirect the planners' stdin and stdout");
    ::close(null);
  }

  // The next line without its newline; false at the end of the input.
  bool read_line(std::string& line) {
    for (;;) {
      const std::size_t end = buffer_.find('\n');
      if (end != std::string::npos) {
        line.assign(buffer_, 0, end);
        buffer_.erase(0, end + 1);
        return true;
      }
      char chunk[65536];
      const ssize_t n = ::read(in_, chunk, sizeof chunk);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) return false;
      buffer_.append(chunk, static_cast<std::size_t>(n));
    }
  }

  // One reply a line (its records are written with bytes that are not UTF-8 as U+FFFD).
  void send(const std::string& line) { write_all(out_, line); }

 private:
  int in_ = -1;
  int out_ = -1;
  std::string buffer_;
};

// A run's reply: its map record, then its run record (engine/outputs/run_record.h), two journal
// lines; the map record holds the references computed so far, which the run record's rebuilt
// metrics divide by.
std::string worker_reply(const MapTaskRun& run) {
  const SweepCell& cell = run.context.plan.cell_of(run.task);
  const int map_index = run.context.plan.map_index_of(run.task);
  const MapFacts facts = run.facts();
  return map_record(cell, map_index, facts) + run_record(cell, map_index, run.planner,
                                                         run_slot_of(run.output),
                                                         run.output.message, facts);
}

// The task loop: each request's runs sent back as they finish; 2 on a malformed request.
int serve_tasks(Channel& channel, const SweepConfig& config, MapTaskWorkspace& workspace) {
  const SweepPlan plan = plan_sweep(config);
  const std::string hash = config_hash(config);
  const MapTaskContext context(config, plan, hash);
  std::int64_t number = 0;
  std::string line;
  while (channel.read_line(line)) {
    ++number;
    TaskRequest request;
    if (const std::string why = read_task_request(line, context, request); !why.empty()) {
      // A malformed request is a bug of whoever sent it: refused by name, never run.
      std::cerr << "agvbench worker: request " << number << ": " << why << "\n";
      return 2;
    }
    run_map_task(context, request.task, request.planners, workspace,
                 [&channel](const MapTaskRun& run) { channel.send(worker_reply(run)); });
  }
  return 0;
}

// The config as run, each plugin's path as the parent sent it in hex when one of them is not
// UTF-8 (JSON would have carried it as U+FFFD: a file that is not there).
nlohmann::json with_plugin_paths(const nlohmann::json& first) {
  nlohmann::json config = first.at("config");
  const auto hex = first.find("plugin_paths_hex");
  if (hex == first.end()) return config;
  nlohmann::json& plugins = config.at("plugins");
  if (!hex->is_array() || hex->size() != plugins.size())
    throw std::invalid_argument("plugin_paths_hex does not match the config's plugins");
  for (std::size_t i = 0; i < plugins.size(); ++i)
    plugins[i]["path"] = from_hex((*hex)[i].get<std::string>());
  return config;
}

}  // namespace

int worker_main(std::int64_t memory_mb) {
  if (memory_mb > 0) {
    const rlim_t bytes = static_cast<rlim_t>(memory_mb) * 1024 * 1024;
    rlimit lim{bytes, bytes};
    if (::setrlimit(RLIMIT_AS, &lim) != 0) {
      std::cerr << "worker: cannot set RLIMIT_AS\n";
      return 1;
    }
  }
  Channel channel;
  std::string line;
  if (!channel.read_line(line)) {
    std::cerr << "agvbench worker: no config line on stdin\n";
    return 2;
  }
  SweepConfig config;
  MapTaskWorkspace workspace;
  try {
    const auto first = nlohmann::json::parse(line);
    // A map source's files are relative to the config's folder, which the parent names (in hex
    // when it is not UTF-8).
    const std::string base_dir = first.contains("base_dir_hex")
                                     ? from_hex(first.at("base_dir_hex").get<std::string>())
                                     : first.value("base_dir", std::string("."));
    config = parse_config(with_plugin_paths(first), base_dir);
    workspace.planners = configure_planners(config);
  } catch (const std::exception& e) {
    channel.send(json_text({{"fatal", e.what()}}) + "\n");
    return 2;
  }
  try {
    channel.send(json_text({{"ready", true}}) + "\n");
    return serve_tasks(channel, config, workspace);
  } catch (const std::runtime_error& e) {  // the parent is gone: nobody to answer
    std::cerr << "agvbench worker: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace agv
