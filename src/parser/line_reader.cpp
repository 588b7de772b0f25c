#include "parser/line_reader.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <algorithm>
#include <cstring>

namespace drycut::parser {

namespace {
constexpr size_t kBufferSize = 256 * 1024;
static_assert(kBufferSize > LineReader::kMaxLineLength);
// Files up to this size are read once and kept: jumps and loops then cost no system call.
constexpr off_t kWholeFileLimit = 16 * 1024 * 1024;
}  // namespace

LineReader::~LineReader() {
  if (fd_ >= 0) ::close(fd_);
}

bool LineReader::open(const std::filesystem::path& path) {
  if (fd_ >= 0) ::close(fd_);
  fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd_ < 0) return false;
  whole_file_ = false;
  struct stat st {};
  if (::fstat(fd_, &st) == 0 && S_ISREG(st.st_mode) && st.st_size <= kWholeFileLimit) {
    buffer_.resize(static_cast<size_t>(st.st_size));
    size_t got = 0;
    while (got < buffer_.size()) {
      const ssize_t n = ::read(fd_, buffer_.data() + got, buffer_.size() - got);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) break;
      got += static_cast<size_t>(n);
    }
    if (got == buffer_.size()) {
      whole_file_ = true;
      seek(LinePosition{});
      return true;
    }
  }
  buffer_.resize(kBufferSize);
  seek(LinePosition{});
  return true;
}

void LineReader::seek(const LinePosition& position) {
  next_position_ = position;
  if (whole_file_) {
    buffer_file_offset_ = 0;
    end_ = buffer_.size();
    begin_ = static_cast<size_t>(std::min<uint64_t>(position.offset, end_));
    eof_ = true;  // nothing more to read: it is all in the buffer
    return;
  }
  begin_ = end_ = 0;
  eof_ = false;
  buffer_file_offset_ = position.offset;
  next_position_ = position;
  if (::lseek(fd_, static_cast<off_t>(position.offset), SEEK_SET) < 0) read_error_ = eof_ = true;
}

bool LineReader::fill() {
  if (eof_) return false;
  if (begin_ > 0) {  // keep the unread tail, drop what was consumed
    std::memmove(buffer_.data(), buffer_.data() + begin_, end_ - begin_);
    buffer_file_offset_ += begin_;
    end_ -= begin_;
    begin_ = 0;
  }
  if (end_ == buffer_.size()) return true;  // full: caller handles the long line
  for (;;) {
    const ssize_t n = ::read(fd_, buffer_.data() + end_, buffer_.size() - end_);
    if (n > 0) {
      end_ += static_cast<size_t>(n);
      return true;
    }
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) read_error_ = true;
    eof_ = true;
    return false;
  }
}

bool LineReader::next(RawLine& out) {
  out.too_long = false;
  out.position = next_position_;
  if (next_position_.offset >= end_offset_) return false;
  if (whole_file_ && begin_ >= end_) return false;  // (an empty file's buffer has no data())
  size_t scanned = begin_;  // no newline in [begin_, scanned)
  for (;;) {
    // An empty file's buffer may have no storage at all: memchr must not see its null pointer.
    const char* nl = scanned < end_ ? static_cast<const char*>(
                                          std::memchr(buffer_.data() + scanned, '\n', end_ - scanned))
                                    : nullptr;
    if (nl && static_cast<size_t>(nl - buffer_.data()) - begin_ > kMaxLineLength) {
      // A whole-file buffer holds the long line: report it as the streaming reader does.
      out.too_long = true;
      out.bytes = std::string_view();
      begin_ = static_cast<size_t>(nl - buffer_.data()) + 1;
      next_position_.offset = buffer_file_offset_ + begin_;
      ++next_position_.line;
      return true;
    }
    if (nl) {
      const size_t line_end = static_cast<size_t>(nl - buffer_.data());
      size_t len = line_end - begin_;
      if (len > 0 && buffer_[begin_ + len - 1] == '\r') --len;
      out.bytes = std::string_view(buffer_.data() + begin_, len);
      begin_ = line_end + 1;
      break;
    }
    if (end_ - begin_ > kMaxLineLength) {
      // Too long: report it and skip the rest chunk by chunk without buffering it.
      out.too_long = true;
      out.bytes = std::string_view();
      begin_ = end_;
      while (fill()) {
        const char* rest_nl =
            static_cast<const char*>(std::memchr(buffer_.data() + begin_, '\n', end_ - begin_));
        if (rest_nl) {
          begin_ = static_cast<size_t>(rest_nl - buffer_.data()) + 1;
          break;
        }
        begin_ = end_;
      }
      next_position_.offset = buffer_file_offset_ + begin_;
      ++next_position_.line;
      return true;
    }
    scanned = end_;
    const size_t before = end_ - begin_;
    if (!fill()) {
      if (end_ == begin_) return false;  // nothing left
      // Last line without a newline.
      size_t len = end_ - begin_;
      if (len > 0 && buffer_[begin_ + len - 1] == '\r') --len;
      out.bytes = std::string_view(buffer_.data() + begin_, len);
      begin_ = end_;
      next_position_.offset = buffer_file_offset_ + begin_;
      ++next_position_.line;
      return true;
    }
    scanned = begin_ + before;  // fill() moved the unread bytes to the front
  }
  next_position_.offset = buffer_file_offset_ + begin_;
  ++next_position_.line;
  return true;
}

}  // namespace drycut::parser
