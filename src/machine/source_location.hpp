#pragma once
// Where a thing came from in a part program: file, 1-based line and column.
#include <cstdint>
#include <memory>
#include <string>

namespace drycut {

struct SourceLocation {
  std::string file;
  uint32_t line = 0;    // 1-based; 0 = not tied to a line
  uint32_t column = 0;  // 1-based; 0 = whole line
};

// The source block a path element or trajectory sample belongs to. The file name is shared
// between all blocks of a file so that carrying it costs one pointer copy.
struct BlockRef {
  std::shared_ptr<const std::string> file;
  uint32_t line = 0;
  std::string text;  // the block as written (trimmed, without the line ending)

  const std::string& file_name() const {
    static const std::string kNone;
    return file ? *file : kNone;
  }
};

}  // namespace drycut
