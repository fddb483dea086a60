#include "engine/plan/output_paths.h"

#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <optional>
#include <system_error>

#include "core/input_error.h"
#include "core/printable.h"
#include "core/text_file.h"

namespace agv {

namespace {

namespace fs = std::filesystem;

std::optional<struct stat> stat_of(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return std::nullopt;
  return st;
}

std::string normalised(const std::string& path) {
  std::error_code ec;
  const fs::path absolute = fs::absolute(path, ec);
  if (ec) return fs::path(path).lexically_normal().string();
  const fs::path resolved = fs::weakly_canonical(absolute, ec);
  return (ec ? absolute.lexically_normal() : resolved).string();
}

[[noreturn]] void refuse(const OutputPath& out, const std::string& reason) {
  throw InputError(out.what + " \"" + printable(out.path, kPathBytes) + "\": " + reason);
}

void check_one(const OutputPath& out) {
  const std::optional<struct stat> st = stat_of(out.path);
  if (st) {
    if (!S_ISREG(st->st_mode)) refuse(out, "is " + file_kind(st->st_mode) + ", not a regular file");
    if (::access(out.path.c_str(), W_OK) != 0)
      refuse(out, std::string("cannot be written: ") + std::strerror(errno));
    if (out.kind == OutputKind::new_journal && st->st_size > 0)
      refuse(out, "already holds a journal (" + std::to_string(st->st_size) +
                      " bytes); continue it with --resume \"" + out.path +
                      "\", or delete it to start afresh");
  } else if (out.kind == OutputKind::appended) {
    refuse(out, std::string("cannot be resumed: ") + std::strerror(errno));
  }
  // The report is renamed into place from a temporary in the same folder, and a new journal is
  // created there: the folder itself must be writable.
  const fs::path parent = fs::path(normalised(out.path)).parent_path();
  const std::optional<struct stat> dir = stat_of(parent.string());
  if (!dir || !S_ISDIR(dir->st_mode))
    refuse(out, "its directory \"" + parent.string() +
                    "\" does not exist (create it first; agvbench creates no directories)");
  if (::access(parent.c_str(), W_OK) != 0)
    refuse(out,
           "its directory \"" + parent.string() + "\" is not writable: " + std::strerror(errno));
}

}  // namespace

bool same_file(const std::string& a, const std::string& b) {
  const std::optional<struct stat> sa = stat_of(a), sb = stat_of(b);
  if (sa && sb) return sa->st_dev == sb->st_dev && sa->st_ino == sb->st_ino;
  return normalised(a) == normalised(b);
}

void check_paths(const std::vector<InputPath>& inputs, const std::vector<OutputPath>& outputs) {
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    const OutputPath& out = outputs[i];
    if (out.path.empty()) continue;
    // The system's calls end a name at its first NUL: the file written would be another one.
    if (out.path.find('\0') != std::string::npos)
      refuse(out, "holds a NUL byte, which no file name can (it would write another file)");
    for (const InputPath& in : inputs)
      if (!in.path.empty() && same_file(out.path, in.path))
        refuse(out, "is the " + in.what + " \"" + printable(in.path, kPathBytes) +
                        "\" (an output never replaces an input)");
    for (std::size_t j = 0; j < i; ++j)
      if (!outputs[j].path.empty() && same_file(out.path, outputs[j].path))
        refuse(out, "is also the " + outputs[j].what + " \"" +
                        printable(outputs[j].path, kPathBytes) +
                        "\" (two outputs cannot share a file)");
    check_one(out);
  }
}

void ignore_file_size_signal() {
  struct sigaction sa {};
  sa.sa_handler = SIG_IGN;
  sigemptyset(&sa.sa_mask);
  ::sigaction(SIGXFSZ, &sa, nullptr);
}

}  // namespace agv
