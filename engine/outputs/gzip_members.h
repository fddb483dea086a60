#pragma once
// A gzip journal (`--runs-out RUNS.jsonl.gz`) is a chain of gzip members, one per write (a map
// task's lines): gzip(1), zcat and Python's gzip module read the chain as one file, and a kill
// can only tear the last member, which resume cuts off as it cuts a torn line (RFC 1952: a gzip
// file is a series of members).

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

struct z_stream_s;  // zlib's, kept out of this header (zlib is the engine's private dependency)

namespace agv {

// Whether the file starts with gzip's magic bytes (false for a missing or empty file).
bool is_gzip_file(const std::string& path);

// Compresses each text into a whole gzip member, reusing one deflate state.
class GzipMemberWriter {
 public:
  GzipMemberWriter();
  ~GzipMemberWriter();
  GzipMemberWriter(const GzipMemberWriter&) = delete;
  GzipMemberWriter& operator=(const GzipMemberWriter&) = delete;

  // The member holding `text`. Throws std::runtime_error if zlib fails (out of memory).
  std::string member(std::string_view text);

 private:
  std::unique_ptr<z_stream_s> stream_;
};

// Inflates a chain of members read in chunks: whole members' text comes out, a member cut
// short never does.
class GzipMemberReader {
 public:
  GzipMemberReader();
  ~GzipMemberReader();
  GzipMemberReader(const GzipMemberReader&) = delete;
  GzipMemberReader& operator=(const GzipMemberReader&) = delete;

  // Feeds the next bytes of the file; appends the text of every member they complete to `out`.
  // Returns false at bytes that are not gzip (the chain is damaged there, or torn: the caller
  // tells which by whether more of the file follows).
  bool feed(std::string_view bytes, std::string& out);
  // Bytes of the file up to the end of the last whole member.
  std::uintmax_t whole_bytes() const { return whole_bytes_; }
  // Whether bytes after the last whole member were fed (a member begun, not finished).
  bool pending() const { return member_bytes_ > 0; }

 private:
  std::unique_ptr<z_stream_s> stream_;
  std::string member_text_;          // the current member's text so far
  std::uintmax_t whole_bytes_ = 0;   // of the file, through the last whole member
  std::uintmax_t member_bytes_ = 0;  // of the file, in the current member
  bool failed_ = false;
};

}  // namespace agv
