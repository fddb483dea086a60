#pragma once
// Bytes from a file or a file name where text is expected: made fit for a one-line message (a
// malformed map can be any bytes, and echoing them raw puts control codes and broken UTF-8 on the
// user's terminal), and carried through JSON, which holds UTF-8 only (hex).

#include <cstddef>
#include <string>
#include <string_view>

namespace agv {

// `text` with every byte that is not printable ASCII or part of a well-formed UTF-8 character
// (control codes, DEL, stray or truncated sequences, overlong forms) written as \xNN, cut after
// `max_bytes` of the input with "... (N more bytes)".
std::string printable(std::string_view text, std::size_t max_bytes = 80);

// A file name quoted whole (PATH_MAX), its odd bytes escaped.
inline constexpr std::size_t kPathBytes = 4096;

// Whether `text` is well-formed UTF-8 (what JSON can carry as it is).
bool is_utf8(std::string_view text);

// Bytes as lowercase hex digits and back: a file name that is not UTF-8 through a JSON channel.
// from_hex throws std::invalid_argument on anything but pairs of hex digits.
std::string to_hex(std::string_view bytes);
std::string from_hex(std::string_view digits);

}  // namespace agv
