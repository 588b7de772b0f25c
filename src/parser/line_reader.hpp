#pragma once
// Streams a program file line by line with a fixed buffer, so a 400 MB program costs no more
// memory than a small one. Every line knows its byte offset, which is what backward jumps and
// loops seek to. A file of at most 16 MiB is read whole once: seeking in it (every loop
// iteration) is then a pointer move, not a system call.
#include <cstdint>
#include <filesystem>
#include <string_view>
#include <vector>

namespace drycut::parser {

// Where a line starts: byte offset in the file and its 1-based line number.
struct LinePosition {
  uint64_t offset = 0;
  uint32_t line = 1;
};

struct RawLine {
  std::string_view bytes;  // without "\n" / "\r\n"; valid until the next call to next()
  LinePosition position;
  bool too_long = false;   // the line exceeded max_line_length; bytes holds only its start
};

class LineReader {
 public:
  // A line longer than this is reported (too_long) and its rest skipped, never buffered.
  static constexpr size_t kMaxLineLength = 64 * 1024;

  LineReader() = default;
  ~LineReader();
  LineReader(const LineReader&) = delete;
  LineReader& operator=(const LineReader&) = delete;

  // False when the file cannot be opened.
  bool open(const std::filesystem::path& path);
  bool next(RawLine& out);
  // Continues reading at a position obtained from an earlier RawLine.
  void seek(const LinePosition& position);
  // Position of the line the next call to next() returns.
  LinePosition tell() const { return next_position_; }
  // Reads end before the line at byte offset `end` (a program's section of an archive file:
  // the next program's % header), as at the end of the file.
  void set_end(uint64_t end) { end_offset_ = end; }
  bool read_error() const { return read_error_; }

 private:
  bool fill();  // reads more bytes behind the unread ones; false at end of file

  int fd_ = -1;
  std::vector<char> buffer_;
  size_t begin_ = 0;  // first unread byte in buffer_
  size_t end_ = 0;    // one past the last valid byte
  uint64_t buffer_file_offset_ = 0;  // file offset of buffer_[0]
  bool eof_ = false;
  bool whole_file_ = false;  // the whole file is in buffer_
  bool read_error_ = false;
  LinePosition next_position_;
  uint64_t end_offset_ = UINT64_MAX;
};

}  // namespace drycut::parser
