#include "parser/line_reader.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace drycut::parser {

namespace {
constexpr size_t kBufferSize = 256 * 1024;
static_assert(kBufferSize > LineReader::kMaxLineLength);
}  // namespace

LineReader::~LineReader() {
  if (fd_ >= 0) ::close(fd_);
}

bool LineReader::open(const std::filesystem::path& path) {
  if (fd_ >= 0) ::close(fd_);
  fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd_ < 0) return false;
  buffer_.resize(kBufferSize);
  seek(LinePosition{});
  return true;
}

void LineReader::seek(const LinePosition& position) {
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
  size_t scanned = begin_;  // no newline in [begin_, scanned)
  for (;;) {
    const char* nl = static_cast<const char*>(
        std::memchr(buffer_.data() + scanned, '\n', end_ - scanned));
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
