#include "machine/source_location.hpp"

#include <mutex>
#include <set>

namespace drycut {

FileName intern_file_name(std::string_view name) {
  // Called when a program file is opened, not per block: a lock is cheap there. Set nodes never
  // move, so the pointers stay valid.
  static std::mutex mutex;
  static std::set<std::string, std::less<>> names;
  const std::lock_guard<std::mutex> lock(mutex);
  auto it = names.find(name);
  if (it == names.end()) it = names.emplace(name).first;
  return &*it;
}

}  // namespace drycut
