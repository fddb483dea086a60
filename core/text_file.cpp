#include "core/text_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "core/input_error.h"
#include "core/printable.h"

namespace agv {

namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what,
                       const std::string& reason) {
  throw InputError(what + " \"" + printable(path, kPathBytes) + "\": " + reason);
}

// The system's calls end a name at its first NUL: the file read would be another one.
void refuse_nul(const std::string& path, const std::string& what) {
  if (path.find('\0') != std::string::npos)
    fail(path, what, "holds a NUL byte, which no file name can (it would read another file)");
}

}  // namespace

std::string file_kind(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

void require_regular_file(const std::string& path, const std::string& what) {
  refuse_nul(path, what);
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) fail(path, what, std::strerror(errno));
  if (!S_ISREG(st.st_mode)) fail(path, what, file_kind(st.st_mode) + ", not a regular file");
  if (::access(path.c_str(), R_OK) != 0) fail(path, what, std::strerror(errno));
}

bool strip_utf8_bom(std::string& text) {
  if (text.size() < 3 || text.compare(0, 3, "\xEF\xBB\xBF") != 0) return false;
  text.erase(0, 3);
  return true;
}

std::string read_text_file(const std::string& path, const std::string& what,
                           std::uintmax_t max_bytes) {
  refuse_nul(path, what);
  // Opened first, then checked through the descriptor: the file checked is the file read.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) fail(path, what, std::strerror(errno));
  struct stat st {};
  if (::fstat(fd, &st) != 0) {
    const int err = errno;
    ::close(fd);
    fail(path, what, std::strerror(err));
  }
  if (!S_ISREG(st.st_mode)) {
    ::close(fd);
    fail(path, what, file_kind(st.st_mode) + ", not a regular file");
  }
  if (static_cast<std::uintmax_t>(st.st_size) > max_bytes) {
    ::close(fd);
    fail(path, what,
         std::to_string(st.st_size) + " bytes, more than the " + std::to_string(max_bytes) +
             " this reader takes");
  }
  std::string text;
  text.reserve(static_cast<std::size_t>(st.st_size));
  char buffer[1 << 16];
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n == 0) break;
    if (n < 0) {
      if (errno == EINTR) continue;
      const int err = errno;
      ::close(fd);
      fail(path, what, std::string("read failed: ") + std::strerror(err));
    }
    text.append(buffer, static_cast<std::size_t>(n));
    if (text.size() > max_bytes) {
      ::close(fd);
      fail(path, what, "grew past " + std::to_string(max_bytes) + " bytes while being read");
    }
  }
  ::close(fd);
  strip_utf8_bom(text);
  return text;
}

}  // namespace agv
