#include "parser/loop_guard.hpp"

namespace drycut::parser {

LoopGuard::Repeat LoopGuard::repeats(uint64_t site, const std::string& state, uint64_t reads,
                                     uint64_t input_reads) {
  constexpr size_t kMaxSites = 4096;  // bounded memory for programs with very many loops
  auto it = sites_.find(site);
  if (it == sites_.end()) {
    if (sites_.size() >= kMaxSites) return Repeat::No;
    it = sites_.emplace(site, Record{}).first;
  }
  Record& r = it->second;
  // A wait on an input is a wait whatever else the stretch read: the input (or a synchronized
  // action's variable) is what ends it on the machine.
  if (r.visits > 0 && r.state == state && r.input_reads != input_reads) return Repeat::WaitsOnInput;
  if (r.visits > 0 && r.reads == reads && r.state == state) return Repeat::Endless;
  if (++r.visits == r.next_save) {
    r.state = state;
    r.reads = reads;
    r.input_reads = input_reads;
    r.next_save *= 2;
  }
  return Repeat::No;
}

}  // namespace drycut::parser
