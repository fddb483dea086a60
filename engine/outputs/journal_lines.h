#pragma once
// A journal's lines, plain JSON Lines or gzip (engine/outputs/gzip_members.h), read in order. What
// a kill may have torn is never returned: a plain file's last line without its newline, or a gzip
// file's last member cut short (all of its lines: they were one write).

#include <cstdint>
#include <fstream>
#include <memory>
#include <string>

#include "engine/outputs/gzip_members.h"

namespace agv {

class JournalLineReader {
 public:
  // Throws InputError naming the journal when it cannot be read.
  explicit JournalLineReader(const std::string& path);

  // The next whole line, without its newline; false at the end. Throws InputError naming the
  // journal for gzip bytes that are damaged (not a torn tail).
  bool next(std::string& line);
  bool gzip() const { return gzip_ != nullptr; }
  // After next() returned false: whether a torn tail was left out, and the bytes of the file
  // before it (where an append continues).
  bool torn() const { return torn_; }
  std::uintmax_t intact_bytes() const { return intact_bytes_; }

 private:
  bool refill();

  std::string path_;
  std::ifstream in_;
  std::unique_ptr<GzipMemberReader> gzip_;
  std::string text_;  // read, not yet returned
  std::size_t pos_ = 0;
  std::uintmax_t plain_bytes_ = 0;  // a plain file's bytes returned as lines
  bool end_ = false;
  bool torn_ = false;
  std::uintmax_t intact_bytes_ = 0;
};

// Whether a journal at this path is written gzip-compressed: an existing file by its first
// bytes, a new or empty one by its name (".gz").
bool journal_is_gzip(const std::string& path);

}  // namespace agv
