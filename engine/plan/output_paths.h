#pragma once
// The files a command reads and writes, checked together before any of them is opened for
// writing: a report or journal may never replace the config, a journal being resumed or merged,
// a map, or another output, and a bad output path is refused (exit 2) before a sweep spends
// hours, not found when its report is written.

#include <string>
#include <vector>

namespace agv {

// A file the command reads; `what` names it in messages ("config file", "--map", "journal").
struct InputPath {
  std::string what;
  std::string path;
};

enum class OutputKind {
  replaced,     // written whole (a report): an existing regular file is replaced
  new_journal,  // a journal started afresh: refused when it exists and is not empty
  appended,     // a journal resumed: it must exist, it is read, then appended to
  database,     // a results database: created, or appended to (never truncated)
};

// A file the command writes; `what` is the option or config field that named it ("--out",
// "report", "--runs-out", "runs", "--resume", "--json-out", "--sqlite", "--db").
struct OutputPath {
  std::string what;
  std::string path;
  OutputKind kind = OutputKind::replaced;
};

// Throws InputError "WHAT \"PATH\": REASON" for the first output that is an input or another
// output (the same file, however spelled: `a/../c.json` or a symbolic link to it), whose folder
// does not exist or is not writable (a folder is never created: a typo is refused rather than
// grown into a tree), that exists and is not a writable regular file, or that is a new journal
// already holding records. Outputs with an empty path are absent and skipped.
void check_paths(const std::vector<InputPath>& inputs, const std::vector<OutputPath>& outputs);

// Whether two paths name the same file: the same device and inode when both exist, else the same
// absolute path once `.`, `..` and the symbolic links of its existing part are resolved.
bool same_file(const std::string& a, const std::string& b);

// Under a file-size limit (ulimit -f) a write past it then fails with EFBIG, which every writer
// reports with the file's name, instead of SIGXFSZ killing the process and leaving a torn file.
void ignore_file_size_signal();

}  // namespace agv
