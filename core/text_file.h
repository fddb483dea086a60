#pragma once
// Reading the user's input files: only regular files are read (a directory, a FIFO or a device
// is refused before it can hang or fill memory), every message names the file and the OS error,
// and a UTF-8 byte-order mark, which editors on some systems write, is skipped.

#include <sys/types.h>

#include <cstdint>
#include <string>

namespace agv {

// Throws InputError "WHAT \"PATH\": REASON" unless PATH names a readable regular file
// (symbolic links followed).
void require_regular_file(const std::string& path, const std::string& what);

// The whole file, its UTF-8 byte-order mark removed; InputError when it is not a readable
// regular file or is larger than max_bytes.
std::string read_text_file(const std::string& path, const std::string& what,
                           std::uintmax_t max_bytes = std::uintmax_t{1} << 30);

// What a file that is not regular is, for messages: "a directory", "a FIFO", "a character
// device", ...
std::string file_kind(mode_t mode);

// Drops a leading UTF-8 byte-order mark (EF BB BF) in place; true when there was one.
bool strip_utf8_bom(std::string& text);

}  // namespace agv
