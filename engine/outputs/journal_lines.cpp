#include "engine/outputs/journal_lines.h"

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "core/input_error.h"

namespace agv {

JournalLineReader::JournalLineReader(const std::string& path)
    : path_(path), in_(path, std::ios::binary) {
  if (!in_) throw InputError("journal \"" + path + "\": " + std::strerror(errno));
  if (is_gzip_file(path)) gzip_ = std::make_unique<GzipMemberReader>();
}

bool JournalLineReader::refill() {
  char chunk[1 << 16];
  in_.read(chunk, sizeof chunk);
  const auto got = static_cast<std::size_t>(in_.gcount());
  if (got == 0) return false;
  text_.erase(0, pos_);
  pos_ = 0;
  if (!gzip_) {
    text_.append(chunk, got);
  } else if (!gzip_->feed({chunk, got}, text_)) {
    throw InputError("journal \"" + path_ + "\": damaged gzip data after byte " +
                     std::to_string(gzip_->whole_bytes()));
  }
  return true;
}

bool JournalLineReader::next(std::string& line) {
  if (end_) return false;
  for (;;) {
    const std::size_t nl = text_.find('\n', pos_);
    if (nl != std::string::npos) {
      line.assign(text_, pos_, nl - pos_);
      plain_bytes_ += nl + 1 - pos_;
      pos_ = nl + 1;
      return true;
    }
    if (!refill()) break;
  }
  end_ = true;
  if (gzip_) {
    // Whole members end in a newline (each is a write of whole lines): text left over, or a
    // member begun, is the torn tail.
    torn_ = gzip_->pending() || pos_ < text_.size();
    intact_bytes_ = gzip_->whole_bytes();
  } else {
    torn_ = pos_ < text_.size();
    intact_bytes_ = plain_bytes_;
  }
  return false;
}

bool journal_is_gzip(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::file_size(path, ec) > 0 && !ec) return is_gzip_file(path);
  return path.size() > 3 && path.compare(path.size() - 3, 3, ".gz") == 0;
}

}  // namespace agv
