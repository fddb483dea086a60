#include "engine/outputs/gzip_members.h"

#include <zlib.h>

#include <fstream>
#include <stdexcept>

namespace agv {

namespace {

// deflateInit2/inflateInit2's windowBits for a gzip wrapper.
constexpr int kGzipWindow = 15 + 16;

}  // namespace

bool is_gzip_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  unsigned char magic[2] = {0, 0};
  in.read(reinterpret_cast<char*>(magic), 2);
  return in.gcount() == 2 && magic[0] == 0x1f && magic[1] == 0x8b;
}

GzipMemberWriter::GzipMemberWriter() : stream_(std::make_unique<z_stream>()) {
  // Level 1: a journal is written under the sinks' lock as tasks finish; the stronger levels
  // take several times longer for a few per cent less (perf/README.md "Sweep memory").
  if (deflateInit2(stream_.get(), 1, Z_DEFLATED, kGzipWindow, 8, Z_DEFAULT_STRATEGY) != Z_OK)
    throw std::runtime_error("zlib: cannot start a gzip stream");
}

GzipMemberWriter::~GzipMemberWriter() { deflateEnd(stream_.get()); }

std::string GzipMemberWriter::member(std::string_view text) {
  if (deflateReset(stream_.get()) != Z_OK)
    throw std::runtime_error("zlib: cannot reset its stream");
  std::string out(deflateBound(stream_.get(), static_cast<uLong>(text.size())), '\0');
  stream_->next_in = reinterpret_cast<Bytef*>(const_cast<char*>(text.data()));
  stream_->avail_in = static_cast<uInt>(text.size());
  stream_->next_out = reinterpret_cast<Bytef*>(out.data());
  stream_->avail_out = static_cast<uInt>(out.size());
  if (deflate(stream_.get(), Z_FINISH) != Z_STREAM_END)
    throw std::runtime_error("zlib: cannot compress a journal write");
  out.erase(out.size() - stream_->avail_out);  // erase, not resize: nothing to fill
  return out;
}

GzipMemberReader::GzipMemberReader() : stream_(std::make_unique<z_stream>()) {
  if (inflateInit2(stream_.get(), kGzipWindow) != Z_OK)
    throw std::runtime_error("zlib: cannot start reading a gzip stream");
}

GzipMemberReader::~GzipMemberReader() { inflateEnd(stream_.get()); }

bool GzipMemberReader::feed(std::string_view bytes, std::string& out) {
  if (failed_) return false;
  stream_->next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
  stream_->avail_in = static_cast<uInt>(bytes.size());
  char chunk[65536];
  while (stream_->avail_in > 0) {
    const uInt before = stream_->avail_in;
    stream_->next_out = reinterpret_cast<Bytef*>(chunk);
    stream_->avail_out = sizeof chunk;
    const int rc = inflate(stream_.get(), Z_NO_FLUSH);
    const std::size_t produced = sizeof chunk - stream_->avail_out;
    member_text_.append(chunk, produced);
    member_bytes_ += before - stream_->avail_in;
    if (rc == Z_STREAM_END) {
      // A whole member: its text is the journal's; the next member starts afresh.
      out += member_text_;
      member_text_.clear();
      whole_bytes_ += member_bytes_;
      member_bytes_ = 0;
      if (inflateReset(stream_.get()) != Z_OK) return !(failed_ = true);
    } else if (rc != Z_OK && !(rc == Z_BUF_ERROR && (before != stream_->avail_in || produced))) {
      return !(failed_ = true);  // damaged, or no way forward
    }
  }
  return true;
}

}  // namespace agv
