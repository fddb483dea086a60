#include "engine/system/file_writes.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace agv {

namespace {

[[noreturn]] void write_failed(const std::string& path, const std::string& tmp,
                               const std::string& doing, int error) {
  ::unlink(tmp.c_str());
  throw std::runtime_error("cannot write \"" + path + "\": " + doing + ": " + std::strerror(error) +
                           " (its temporary \"" + tmp +
                           "\" was removed; the previous file, if any, is intact)");
}

// Removes `NAME.tmp.PID` beside `target` whose process is gone: a write killed before its rename
// (or a crash) left it. A temporary of a live process is another writer's, left alone.
void remove_stale_temporaries(const std::filesystem::path& target) {
  namespace fs = std::filesystem;
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  const std::string prefix = target.filename().string() + ".tmp.";
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.size() <= prefix.size() || name.compare(0, prefix.size(), prefix) != 0) continue;
    const std::string digits = name.substr(prefix.size());
    if (digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 9) continue;
    const pid_t pid = static_cast<pid_t>(std::stol(digits));
    if (pid == ::getpid()) continue;
    if (::kill(pid, 0) == 0 || errno != ESRCH) continue;
    std::error_code ignored;
    if (it->is_regular_file(ignored)) fs::remove(it->path(), ignored);
  }
}

}  // namespace

int write_whole(int fd, std::string_view data, std::size_t& written) {
  written = 0;
  while (written < data.size()) {
    const ssize_t n = ::write(fd, data.data() + written, data.size() - written);
    if (n < 0 && errno == EINTR) continue;
    // A zero-byte write of a non-empty buffer makes no progress: treated as a full disk.
    if (n <= 0) return n < 0 ? errno : ENOSPC;
    written += static_cast<std::size_t>(n);
  }
  return 0;
}

void write_file_atomic(std::string_view text, const std::string& path) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  remove_stale_temporaries(target);
  const std::string tmp = path + ".tmp." + std::to_string(getpid());
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) write_failed(path, tmp, "cannot create its temporary", errno);
  std::size_t written = 0;
  if (const int error = write_whole(fd, text, written); error != 0) {
    ::close(fd);
    write_failed(path, tmp, "write failed", error);
  }
  if (::fsync(fd) != 0) {
    const int error = errno;
    ::close(fd);
    write_failed(path, tmp, "fsync failed", error);
  }
  if (::close(fd) != 0) write_failed(path, tmp, "close failed", errno);
  if (std::rename(tmp.c_str(), path.c_str()) != 0) write_failed(path, tmp, "rename failed", errno);
  // The rename itself is durable once the folder is synced.
  const std::string dir = target.has_parent_path() ? target.parent_path().string() : ".";
  const int dir_fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir_fd >= 0) {
    ::fsync(dir_fd);
    ::close(dir_fd);
  }
}

}  // namespace agv
