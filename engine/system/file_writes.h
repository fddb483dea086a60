#pragma once
// The file writes whose failure must never pass unnoticed: one loop that writes a buffer whole
// (the journal's appends, the report's temporary, the isolation channel), and the atomic
// replacement of a file (reports, `plan --json-out`).

#include <cstddef>
#include <string>
#include <string_view>

namespace agv {

// Writes all of `data` to `fd`, retrying after EINTR and short writes. Returns 0, or the errno of
// the failure (ENOSPC for a write that makes no progress); `written` says how much got out.
int write_whole(int fd, std::string_view data, std::size_t& written);

// Temporary file in the same folder, fsync, rename, folder synced: a reader (or a crash) sees the
// old file or the new one, never a torn one. The folder must exist (engine/plan/output_paths.h
// checks it before a sweep); temporaries of this path left by a process that is gone are removed
// first. Throws std::runtime_error naming `path` and the OS error; the old file is then intact.
void write_file_atomic(std::string_view text, const std::string& path);

}  // namespace agv
