#pragma once
// Where a thing came from in a part program: file, 1-based line and column.
#include <cstdint>
#include <string>
#include <string_view>

namespace drycut {

struct SourceLocation {
  std::string file;
  uint32_t line = 0;    // 1-based; 0 = not tied to a line
  uint32_t column = 0;  // 1-based; 0 = whole line
};

// A file name kept for the life of the process (interned once per name, never freed): blocks and
// path elements carry the pointer, which costs a plain copy. (Until 2026-11-28 it was a
// shared_ptr: every element copied and released its count from the interpreter's thread and the
// planner's, a cache line bouncing between the cores, 12 % of a G1 run's CPU time.)
using FileName = const std::string*;
FileName intern_file_name(std::string_view name);

// The source block a path element or trajectory sample belongs to.
struct BlockRef {
  FileName file = nullptr;
  uint32_t line = 0;
  std::string text;  // the block as written (trimmed, without the line ending)

  const std::string& file_name() const {
    static const std::string kNone;
    return file ? *file : kNone;
  }
};

}  // namespace drycut
